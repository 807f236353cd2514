# The signals of Palletizer.mod (format: doc/controller.md): both pallets empty, a box always
# waiting at the pick position, the vacuum and the sheet gripper confirm at once. The program
# palletises until the virtual time runs out (its main loop has no end).
signal diBoxAtPick di 1
signal diPallet1Empty di 1
signal diPallet2Empty di 1
signal diSheetGripped di 1
signal diVacuumOk di 1
signal doBlowOff do
signal doSheetVacuum do
signal doVacuum do
