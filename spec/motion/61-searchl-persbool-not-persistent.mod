MODULE searchl_persbool_var
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 13:20
! @description SearchL's PersBool (ABB, RAPID Instructions) is a persistent bool: a variable bool in the place of Signal | PersBool is refused, as a persistent is where a signal is asked for.
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR bool vTouch := FALSE;
  VAR signaldi di_part;
  PROC main()
    VAR robtarget found;
    SearchL \Stop, di_part, found, p2, v100, tool0;
    SearchL \Stop, vTouch, found, p2, v100, tool0;
  ENDPROC
ENDMODULE
