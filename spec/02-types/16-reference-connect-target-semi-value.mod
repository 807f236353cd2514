MODULE reference_connect_target_semi
! @format 2
! @section 2.16
! @section 4.15
! @expect semantic-error 9:13
! @description A signaldi cannot be updated by value, so it is no connect target; refused at the target.
  VAR signaldi sig1;
  PROC main()
    CONNECT sig1 WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
