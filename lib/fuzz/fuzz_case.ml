type options = {
  allow_unknown : bool;
  stub_unmodelled : bool;
  max_time : float option;
  max_memory : int option;
  max_call_depth : int option;
}

let default_options =
  { allow_unknown = false; stub_unmodelled = false; max_time = None; max_memory = None; max_call_depth = None }

let limits o =
  let d = Rapid_runtime.Limits.default in
  { d with max_call_depth = Option.value o.max_call_depth ~default:d.max_call_depth;
           max_memory = Option.value o.max_memory ~default:d.max_memory }

let arguments o =
  (if o.allow_unknown then [ "--allow-unknown" ] else [])
  @ (if o.stub_unmodelled then [ "--stub-unmodelled" ] else [])
  @ (match o.max_time with Some t -> [ "--max-time"; Printf.sprintf "%g" t ] | None -> [])
  @ (match o.max_memory with Some m -> [ "--max-memory"; string_of_int m ] | None -> [])
  @ (match o.max_call_depth with Some d -> [ "--max-call-depth"; string_of_int d ] | None -> [])

type task = { task_name : string; modules : Program_gen.program list }

type t = { tasks : task list; io_text : string; options : options; schedule : int option }

(* A module's name may carry its attributes ("tools (NOSTEPIN)"), which the printer writes
   after MODULE: the file takes the bare name. *)
let module_file (p : Program_gen.program) =
  let bare = match String.index_opt p.name ' ' with Some i -> String.sub p.name 0 i | None -> p.name in
  bare ^ ".mod"

let size c =
  List.fold_left (fun n t -> List.fold_left (fun n m -> n + Program_gen.size m) n t.modules) 0 c.tasks

let shrink c =
  let replace_nth l i x = List.mapi (fun j y -> if i = j then x else y) l in
  List.to_seq (List.mapi (fun ti t -> (ti, t)) c.tasks)
  |> Seq.flat_map (fun (ti, t) ->
      List.to_seq (List.mapi (fun mi m -> (mi, m)) t.modules)
      |> Seq.flat_map (fun (mi, m) ->
          Seq.map (fun m' -> { c with tasks = replace_nth c.tasks ti { t with modules = replace_nth t.modules mi m' } })
            (Program_gen.shrink m)))

let command c =
  let files t = String.concat "," (List.map module_file t.modules) in
  let tasks = match c.tasks with
    | [ t ] -> [ String.concat " " (List.map module_file t.modules) ]
    | ts -> List.map (fun t -> Printf.sprintf "--task %s=%s" t.task_name (files t)) ts in
  String.concat " "
    ([ "rapid-sem run" ] @ arguments c.options @ [ "--io fuzz.io" ]
     @ (match c.schedule with Some s when List.length c.tasks > 1 -> [ "--schedule"; string_of_int s ] | _ -> [])
     @ tasks)

let to_text c =
  String.concat ""
    (Printf.sprintf "! %s\n" (command c)
     :: List.concat_map (fun t ->
         List.map (fun m ->
             Printf.sprintf "! task %s, file %s\n%s" t.task_name (module_file m) (Program_gen.to_source m))
           t.modules) c.tasks)
