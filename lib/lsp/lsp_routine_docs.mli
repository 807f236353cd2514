(** One line, in rapid-sem's own words, of what an installed routine does: what a hover and a
    completion item show beside its signature (lib/typing/installed/*.sys). The facts are those
    of ABB's documentation of each routine (installed-facts.md); a routine without a line here
    is shown with its signature only. *)

val find : string -> string option
(** By name, letter case aside (§2.3). *)

val names : string list
