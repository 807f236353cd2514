(** The FlexPendant's dialogues (TPReadFK, TPReadNum, UIMsgBox, UIMessageBox, UINumEntry,
    UINumTune, UIAlphaEntry, UIListView) and UIClientExist, answered by the run's scripted
    operator ({!Rapid_controller.Operator_script}, --operator; doc/rulings.md R-13-ui2). *)

val names : string list

val claims : Rapid_controller.World.t -> string -> bool
(** One of {!names}, in a world whose services have an operator: without one the dialogues are
    not modelled (R-13-i) and UIClientExist is FALSE (R-13-ui1). *)

val call : Primitive.context -> string -> Primitive.argument array -> Primitive.outcome option
