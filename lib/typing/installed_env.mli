(** The installed environment (ch. 13): the RAPID modules of lib/typing/installed, which declare
    the installed types, data and routine signatures that programs use (MoveL, TPWrite, tooldata,
    v100, ...). They are read with the two things only installed code may use: the access mode
    REF and the type anytype (ch. 11). Their routines' bodies are bound to primitives by name
    when a program runs. *)

open Rapid_syntax

val modules : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** Parsed once, on first use, or taken from the image {!set_image} names. An [Error] is a bug of
    rapid-sem's own sources. *)

val parse : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** Parses them now (what {!modules} does without an image): for the build-time image. *)

val set_image : (unit -> Ast.module_declaration list) -> unit
(** Before the first {!modules}: where it takes the installed modules from, the image of them
    (parsed, checked and lowered when rapid-sem was built, lib/load/installed_image.ml) that
    also restores what their parse, check and lowering left behind (their files' ids, the
    record types' ids, the checker's and the lowering's shared state). *)

val test_modules : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** The assertions of rapid-sem test (installed/unit_test.sys), which {!modules} leaves out: only
    the task buffers that command runs have them (doc/rulings.md R-test-a). *)

val file_names : string list
(** The names of every installed file, the assertions' among them. *)
