(** The answers to the editor's requests about a position or a name, from a task's index
    ({!Lsp_index}) and the texts of its modules. Each returns the [result] of LSP 3.17's
    response, or raises {!Refused} with the reason a rename is refused. *)

exception Refused of string

val hover : Lsp_workspace.t -> string -> Lsp_text.position -> Yojson.Safe.t
(** A data object's declaration and type; a routine's signature, and for an installed routine
    one line of what it does (doc/editor.md); a type's definition. [null] off a name. *)

val definition : Lsp_workspace.t -> string -> Lsp_text.position -> Yojson.Safe.t
(** The declaration's location, in whichever module of the task; [[]] for an installed name
    (its declaration is inside rapid-sem) or off a name. *)

val references : Lsp_workspace.t -> string -> Lsp_text.position -> include_declaration:bool -> Yojson.Safe.t

val document_symbols : Lsp_workspace.t -> string -> Yojson.Safe.t
(** The module, its types, data and routines, and in each routine its parameters, data and
    labels: DocumentSymbol[]. *)

val workspace_symbols : Lsp_workspace.t -> string -> Yojson.Safe.t
(** The module-level declarations of every task whose name contains the query (letter case
    aside): SymbolInformation[]. *)

val completion : Lsp_workspace.t -> string -> Lsp_text.position -> snippets:bool -> Yojson.Safe.t
(** After [.]: the components of the reference's record type; after [\]: the optional
    parameters of the routine called on the line; elsewhere: the names in scope, installed
    routines with their parameters (as snippets when the client takes them). *)

val signature_help : Lsp_workspace.t -> string -> Lsp_text.position -> Yojson.Safe.t
(** The signature of the routine called on the line (the innermost open function call, else the
    procedure call), its parameters, and the one the cursor is at: the required parameter
    after as many commas as stand before the cursor. *)

val code_actions : Lsp_workspace.t -> string -> Yojson.Safe.t list -> Yojson.Safe.t
(** Quick fixes for the diagnostics the client names: for a hint "did you mean tool0?" (or
    "a, b or c?") on a diagnostic whose range holds one name, an edit to each suggested name. *)

val prepare_rename : Lsp_workspace.t -> string -> Lsp_text.position -> Yojson.Safe.t

val rename : Lsp_workspace.t -> string -> Lsp_text.position -> string -> Yojson.Safe.t
(** A WorkspaceEdit that renames the declaration and every use in the task. Refused (raises
    {!Refused}) for an installed name, a new name that is not an identifier (§2.3: a letter,
    then letters, digits and underscores, at most 32 characters, not a reserved word of §2.4),
    and one that is already declared where the name is visible or that a use would then
    denote instead. *)

val valid_identifier : string -> (unit, string) result

val suggested : string -> string list
(** The names of a hint ["did you mean a, b or c?"]; none for another hint. *)
