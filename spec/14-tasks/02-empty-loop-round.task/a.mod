MODULE loop_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description A new round of a loop whose body has no statement ends the turn, as a statement does (R-14-o): each FOR step of an empty body is a turn of its own, so T_B writes between them.
! @output B 1
! @output B 2
! @output B 3
! @output A after
! @output B 4
  PROC main()
    FOR k FROM 1 TO 3 DO
    ENDFOR
    TPWrite "A after";
  ENDPROC
ENDMODULE
