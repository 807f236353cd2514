(* The static half of the oracle's protocol (doc/oracle.md): whether a task buffer is accepted,
   written as an event stream like run --json's, so that a conformance runner can ask any
   implementation the same question for cases of formats 1 and 2. *)

module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
open Rapid_syntax

let schema = Rapid_oracle.Event_json.schema

let start_line : Yojson.Safe.t = Rapid_oracle.Event_json.start ()

(* The class as spec/README.md's @expect spells it. *)
let class_word = function
  | Diagnostic.Lexical_error -> "lexical-error"
  | Syntax_error -> "syntax-error"
  | Semantic_error -> "semantic-error"
  | Fatal_static_error -> "fatal-error"
  | File_error -> "file-error"

let region_json r : Yojson.Safe.t =
  let p = Source.start r and q = Source.stop r in
  `Assoc [ ("file", `String (match Source.file_of r with Some f -> Source.name f | None -> ""));
           ("line", `Int p.line); ("col", `Int p.col); ("end_line", `Int q.line); ("end_col", `Int q.col) ]

let refused (d : Diagnostic.t) : Yojson.Safe.t =
  `Assoc [ ("event", `String "end"); ("outcome", `String "refused");
           ("class", `String (class_word d.error_class)); ("at", region_json d.region);
           ("message", `String (Rapid_runtime.Utf8_text.of_bytes d.message)) ]

let accepted : Yojson.Safe.t = `Assoc [ ("event", `String "end"); ("outcome", `String "accepted") ]

let first_error (reports : Rapid_typing.Report.t list) =
  List.find_opt (fun (r : Rapid_typing.Report.t) -> r.severity = Error) reports

(* The stream of a task buffer refused before it runs: the first error. *)
let stream_of_failure : Rapid_load.Session.failure -> Yojson.Safe.t list option = function
  | Front_end (d :: _) -> Some [ start_line; refused d ]
  | Static reports -> (
      match first_error reports with
      | Some r -> Some [ start_line; refused (Rapid_typing.Report.to_diagnostic r) ]
      | None -> None)
  | Front_end [] | Internal _ -> None

open Cmdliner

let cmd =
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
  let stage =
    Arg.(value & opt (enum [ ("parse", `Parse); ("check", `Check) ]) `Check & info [ "stage" ] ~docv:"STAGE"
           ~doc:"$(b,parse): the front end only (decoding, lexing, parsing, the nesting limit), as \
                 format 1 of spec/README.md judges; $(b,check) (the default): the static \
                 semantics too, the initial values of data included, as format 2 judges.")
  in
  let strict = Arg.(value & flag & info [ "strict" ] ~doc:"Refuse the dialect extensions of doc/dialect.md.") in
  let allow_unknown = Arg.(value & flag & info [ "allow-unknown" ] ~doc:"Unknown names are warnings.") in
  let run files stage strict allow_unknown io =
    let print l = List.iter (fun j -> print_endline (Json_text.to_string j)) l in
    match Rapid_run.Run_setup.read_io io with
    | Error m -> prerr_endline m; 2
    | Ok io -> (
        let options = { Parse.default_options with strict } in
        match stage with
        | `Parse -> (
            let parsed = List.map (Parse.parse_file ~options) files in
            match List.find_map (function Error d -> Some d | Ok _ -> None) parsed with
            | Some d -> print [ start_line; refused d ]; 2
            | None -> print [ start_line; accepted ]; 0)
        | `Check -> (
            match Rapid_load.Session.load ~strict ~allow_unknown ~io files with
            | Ok _ -> print [ start_line; accepted ]; 0
            | Error f -> (
                match stream_of_failure f with
                | Some l -> print l; 2
                | None -> prerr_endline "rapid-sem: internal error: refused without a diagnostic"; 125)))
  in
  let doc = "say whether a task buffer is accepted, as an event stream (the oracle's protocol)" in
  let man = [
    `S Manpage.s_description;
    `P "Writes the start line of $(b,run --json) and one end object: \
        $(b,{\"event\":\"end\",\"outcome\":\"accepted\"}), or $(b,\"refused\") with the first error's class (as \
        spec/README.md's @expect spells it), region and message. $(b,rapid-sem spec --impl) asks implementations \
        this question for the cases of formats 1 and 2 (doc/oracle.md).";
    `S Manpage.s_exit_status; `P "0 accepted; 2 refused.";
  ] in
  Cmd.v (Cmd.info "verdict" ~doc ~man) Term.(const run $ files $ stage $ strict $ allow_unknown $ Run_args.io_arg)
