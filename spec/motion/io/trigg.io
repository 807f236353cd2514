# The signals of the spec/motion cases of TriggL, TriggJ, TriggC and their triggers (54 to 59;
# format: doc/controller.md).
signal do_gun do
signal do_aux do
signal go_code go
signal ao_flow ao
