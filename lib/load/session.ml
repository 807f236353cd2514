open Rapid_syntax

type loaded = { program : Ir.program; warnings : Rapid_typing.Report.t list; unknown_summary : string option }

type failure =
  | Front_end of Diagnostic.t list
  | Static of Rapid_typing.Report.t list
  | Internal of string

module Io = Rapid_controller.Io_config

(* The signals of the I/O configuration are installed data objects of the signal types
   (§2.16): a generated installed module declares them, so that the checker knows them. *)
let signal_module_name = "Installed_signals"

let signal_file_name = "the signals of the I/O configuration"

(* A name MOC.cfg gives that is a RAPID identifier (§2.3) and no reserved word (§2.4). *)
let identifier u =
  Lexer.is_ascii_name u && not (Hashtbl.mem Lexer.reserved_words (String.uppercase_ascii u))

(* R-bk-13: a backup's mechanical units are mecunit data objects as ROB_1 .. ROB_4 are; those
   four are installed already, and a unit named as a signal is the signal. *)
let installed_units = [ "rob_1"; "rob_2"; "rob_3"; "rob_4" ]

let unit_names (io : Io.t) =
  let taken = installed_units @ List.map (fun (s : Io.signal) -> String.lowercase_ascii s.name) io.signals in
  List.fold_left (fun acc u ->
      let k = String.lowercase_ascii u in
      if List.mem k taken || List.exists (fun a -> String.lowercase_ascii a = k) acc || not (identifier u) then acc
      else acc @ [ u ]) [] io.mechanical_units

(* R-14-taskid: each program task's predefined taskid variable, NAMEId, when it is a name (§2.3)
   no signal or unit has taken. *)
let task_id_names (io : Io.t) ~units =
  let taken = installed_units @ List.map String.lowercase_ascii units
              @ List.map (fun (s : Io.signal) -> String.lowercase_ascii s.name) io.signals in
  List.filter_map (fun t ->
      let v = t ^ "Id" in
      if List.mem (String.lowercase_ascii v) taken || not (identifier v) then None else Some v) io.task_ids

let signal_text (io : Io.t) =
  let units = unit_names io in
  let ids = task_id_names io ~units in
  if io.signals = [] && units = [] && ids = [] then None
  else
    let text = Buffer.create 256 in
    Buffer.add_string text ("MODULE " ^ signal_module_name ^ " (SYSMODULE)\n");
    List.iter (fun (s : Io.signal) ->
        Buffer.add_string text (Printf.sprintf "  VAR %s %s;\n" (Io.type_name s.kind) s.name)) io.signals;
    List.iter (fun u -> Buffer.add_string text (Printf.sprintf "  VAR mecunit %s;\n" u)) units;
    List.iter (fun v -> Buffer.add_string text (Printf.sprintf "  VAR taskid %s;\n" v)) ids;
    Buffer.add_string text "ENDMODULE\n";
    Some (Buffer.contents text)

let signal_module text =
  match text with
  | None -> Ok None
  | Some text -> (
      match Parse.parse_string ~options:{ Parse.default_options with installed = true }
              ~name:signal_file_name text with
      | Ok m -> Ok (Some m)
      | Error d -> Error d)

(* The installed environment computed at build time (Installed_image), which this reference
   links into every program that loads a task. *)
let () = ignore (Installed_image.in_use ())

(* The last list made, with what it was made from: the checker and the lowering keep what they
   compute for the installed level by the list itself (compared physically), so a new list for
   the same signals (each task of a run, each scenario of the fuzzer) would have the whole
   installed level checked and lowered again. *)
let last_installed = ref None

let installed ?(testing = false) ?(io = Io.empty) () =
  let text = signal_text io in
  match !last_installed with
  | Some (testing', text', result) when testing' = testing && text' = text -> result
  | _ ->
      let tests = if testing then Rapid_typing.Installed_env.test_modules () else Ok [] in
      (* the installed level's list itself when nothing is added: the checker and the lowering
         know the build-time image's level by that list (Check.installed_state) *)
      let ( @@@ ) l = function [] -> l | more -> l @ more in
      let result =
        match tests, signal_module text with
        | Error d, _ | _, Error d -> Error d
        (* nothing added: the level's headers, without reading the declarations' trees *)
        | Ok [], Ok None -> Rapid_typing.Installed_env.level ()
        | Ok tests, Ok signals -> (
            match Rapid_typing.Installed_env.modules () with
            | Error d -> Error d
            | Ok installed -> Ok (installed @@@ tests @@@ Option.to_list signals)) in
      last_installed := Some (testing, text, result);
      result

(* Each declared signal object denotes its signal of the world: identity i for the i-th signal
   of the configuration (Rapid_controller.World.signals). *)
let connect_signals (io : Io.t) (program : Ir.program) =
  (* a table of the signals' names (letter case aside, §2.3), so that connecting n signals
     takes n look-ups, not n * n comparisons *)
  let ids = Hashtbl.create (List.length io.signals) in
  List.iteri (fun i (s : Io.signal) ->
      let key = String.lowercase_ascii s.name in
      if not (Hashtbl.mem ids key) then Hashtbl.replace ids key (i + 1, s)) io.signals;
  let same = Rapid_typing.Types.same_name in
  (* R-14-taskid: a taskid's identity is its task's number (1 for the first task of the run). *)
  let task_numbers = Hashtbl.create 8 in
  List.iteri (fun k t -> Hashtbl.replace task_numbers (String.lowercase_ascii (t ^ "Id")) (k + 1)) io.task_ids;
  let globals = Array.map (fun (g : Ir.global) ->
      if not (same g.g_module signal_module_name) then g
      else
        match Hashtbl.find_opt ids (String.lowercase_ascii g.g_name) with
        | None -> (
            match Hashtbl.find_opt task_numbers (String.lowercase_ascii g.g_name) with
            | Some k ->
                let handle = Value.Handle (Value.make_handle ~kind:"taskid" k) in
                { g with g_init = Init_expr { e = Literal handle; at = g.g_at } }
            | _ -> g)
        | Some (i, s) ->
            let handle = Value.Handle (Value.make_handle ~kind:(Io.type_name s.kind) i) in
            { g with g_init = Init_expr { e = Literal handle; at = g.g_at } }) program.globals in
  { program with globals }

(* The program of a checked task, its signals connected and the initial values of its data
   computed: they are known before the run (§3.2), so their errors are static. *)
let lower ?(io = Io.empty) ~installed ~modules (result : Rapid_typing.Check.result) =
  Initial_values.evaluate (connect_signals io (Lower.program ~installed ~modules result.elaboration))

(* The checker's reports on the generated module of the signals (a signal named after an
   installed object, §13) belong where the I/O configuration names the signal: line k + 1 of
   that module declares its k-th signal. The place becomes a region of a file of the
   configuration's name whose lines 1 .. L-1 are one character long, so that its line L,
   column C is the offset L - 1 + C - 1. *)
let at_io_place (io : Io.t) =
  let signals = lazy (Array.of_list io.signals) in
  fun (r : Rapid_typing.Report.t) ->
    match Source.file_of r.region with
    | Some f when Source.name f = signal_file_name ->
        let signals = Lazy.force signals in
        let k = (Source.start r.region).line - 2 in
        if k < 0 || k >= Array.length signals || signals.(k).line < 1 then r
        else
          let s = signals.(k) in
          let file = Source.register ~name:io.file ~line_starts:(Array.init s.line (fun i -> i)) in
          let start = s.line - 1 + s.col - 1 in
          { r with region = Source.region file start (start + String.length s.name) }
    | _ -> r

let load_modules ?testing ?(allow_unknown = false) ?(io = Io.empty) modules =
  match installed ?testing ~io () with
  | Error d -> Error (Internal ("the installed environment does not parse: " ^ Diagnostic.to_string d))
  | Ok installed ->
      let result = Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
      if Rapid_typing.Check.errors result <> [] then Error (Static (List.map (at_io_place io) result.reports))
      else
        match lower ~io ~installed ~modules result with
        | Ok program ->
            Ok { program; warnings = result.reports; unknown_summary = Rapid_typing.Check.unknown_summary result }
        | Error reports -> Error (Static (result.reports @ reports))

let load_files ~strict ~robotware ?testing ?allow_unknown ?io files =
  let options = { Parse.default_options with strict; robotware } in
  let parsed = List.map (Parse.parse_file ~options) files in
  match List.filter_map (function Error d -> Some d | Ok _ -> None) parsed with
  | [] -> load_modules ?testing ?allow_unknown ?io (List.filter_map Result.to_option parsed)
  | errors -> Error (Front_end errors)

(* Most of what loading allocates lives on: the collector is slowed down meanwhile
   (Build_pace). *)
let load ?(strict = false) ?(robotware = Robotware.default) ?testing ?allow_unknown ?io files =
  Build_pace.building (fun () -> load_files ~strict ~robotware ?testing ?allow_unknown ?io files)

(* rapid-sem test (doc/testing.md, R-test-a): a test is a parameterless procedure named test_...,
   letter case aside (§2.3). *)
let is_test_name n = String.length n > 5 && String.lowercase_ascii (String.sub n 0 5) = "test_"

let declares_tests (m : Ast.module_declaration) =
  List.exists (fun (r : Ast.routine_declaration) -> match r.it with
      | Procedure_declaration { name = { it = Ident n; _ }; parameters = []; _ } -> is_test_name n
      | _ -> false) m.routine_declarations
