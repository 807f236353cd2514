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

let signal_module (io : Io.t) =
  if io.signals = [] then Ok None
  else
    let text = Buffer.create 256 in
    Buffer.add_string text ("MODULE " ^ signal_module_name ^ " (SYSMODULE)\n");
    List.iter (fun (s : Io.signal) ->
        Buffer.add_string text (Printf.sprintf "  VAR %s %s;\n" (Io.type_name s.kind) s.name)) io.signals;
    Buffer.add_string text "ENDMODULE\n";
    match Parse.parse_string ~options:{ Parse.default_options with installed = true }
            ~name:"the signals of the I/O configuration" (Buffer.contents text) with
    | Ok m -> Ok (Some m)
    | Error d -> Error d

let installed ?(io = Io.empty) () =
  match Rapid_typing.Installed_env.modules (), signal_module io with
  | Error d, _ | _, Error d -> Error d
  | Ok installed, Ok None -> Ok installed
  | Ok installed, Ok (Some m) -> Ok (installed @ [ m ])

(* Each declared signal object denotes its signal of the world: identity i for the i-th signal
   of the configuration (Rapid_controller.World.signals). *)
let connect_signals (io : Io.t) (program : Ir.program) =
  (* without lowered copies: every installed data object is compared, for every program *)
  let same = Rapid_typing.Types.same_name in
  let globals = Array.map (fun (g : Ir.global) ->
      if not (same g.g_module signal_module_name) then g
      else
        let rec find i = function
          | [] -> g
          | (s : Io.signal) :: rest ->
              if same s.name g.g_name then
                let handle = Value.Handle (Value.make_handle ~kind:(Io.type_name s.kind) i) in
                { g with g_init = Init_expr { e = Literal handle; at = g.g_at } }
              else find (i + 1) rest in
        find 1 io.signals) program.globals in
  { program with globals }

(* The program of a checked task, its signals connected and the initial values of its data
   computed: they are known before the run (§3.2), so their errors are static. *)
let lower ?(io = Io.empty) ~installed ~modules (result : Rapid_typing.Check.result) =
  Initial_values.evaluate (connect_signals io (Lower.program ~installed ~modules result.elaboration))

let load_modules ?(allow_unknown = false) ?(io = Io.empty) modules =
  match installed ~io () with
  | Error d -> Error (Internal ("the installed environment does not parse: " ^ Diagnostic.to_string d))
  | Ok installed ->
      let result = Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
      if Rapid_typing.Check.errors result <> [] then Error (Static result.reports)
      else
        match lower ~io ~installed ~modules result with
        | Ok program ->
            Ok { program; warnings = result.reports; unknown_summary = Rapid_typing.Check.unknown_summary result }
        | Error reports -> Error (Static (result.reports @ reports))

let load ?(strict = false) ?allow_unknown ?io files =
  let options = { Parse.default_options with strict } in
  let parsed = List.map (Parse.parse_file ~options) files in
  match List.filter_map (function Error d -> Some d | Ok _ -> None) parsed with
  | [] -> load_modules ?allow_unknown ?io (List.filter_map Result.to_option parsed)
  | errors -> Error (Front_end errors)
