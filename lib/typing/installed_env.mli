(** The installed environment (ch. 13): the RAPID modules of lib/typing/installed, which declare
    the installed types, data and routine signatures that programs use (MoveL, TPWrite, tooldata,
    v100, ...). They are read with the two things only installed code may use: the access mode
    REF and the type anytype (ch. 11). Their routines' bodies are bound to primitives by name
    when a program runs. *)

open Rapid_syntax

val modules : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** The installed modules with their declarations: parsed once, on first use, or taken from the
    image {!set_image} names. An [Error] is a bug of rapid-sem's own sources. *)

val level : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** The list to check and lower a task over: with an image, its modules' headers (names,
    attributes, regions, no declarations), which the image's checked and lowered state is keyed
    by, so that a run that needs no declaration's tree never reads them; without, {!modules}. *)

val full : Ast.module_declaration list -> Ast.module_declaration list
(** The modules with their declarations of a list that may be {!level}'s headers (any other list
    is its own): what a check or a lowering that does not start from the image's state reads. *)

val same : Ast.module_declaration list -> Ast.module_declaration list -> bool
(** The same installed level: the same list (physically), or {!level}'s headers and {!modules}'
    list once both were read. *)

val parse : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** Parses them now (what {!modules} does without an image): for the build-time image. *)

val set_image :
  level:(unit -> Ast.module_declaration list) -> trees:(unit -> Ast.module_declaration list) -> unit
(** Before the first {!modules} or {!level}: where they come from, the image of them (parsed,
    checked and lowered when rapid-sem was built, lib/load/installed_image.ml). [level] reads the
    state that also restores what their parse, check and lowering left behind (their files' ids,
    the record types' ids, the checker's and the lowering's shared state) and gives the headers;
    [trees], called after it, the modules with their declarations. *)

val test_modules : unit -> (Ast.module_declaration list, Diagnostic.t) result
(** The assertions of rapid-sem test (installed/unit_test.sys), which {!modules} leaves out: only
    the task buffers that command runs have them (doc/rulings.md R-test-a). *)

val file_names : string list
(** The names of every installed file, the assertions' among them. *)
