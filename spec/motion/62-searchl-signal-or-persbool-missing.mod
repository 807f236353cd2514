MODULE searchl_choice_missing
! @format 2
! @section 4.6
! @section 13
! @expect semantic-error 10:20
! @description SearchL takes exactly one of Signal | PersBool (ABB, RAPID Instructions): an argument of neither type in that place (a num) is refused there, judged against Signal.
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget found;
    SearchL \Stop, 5, found, p2, v100, tool0;
  ENDPROC
ENDMODULE
