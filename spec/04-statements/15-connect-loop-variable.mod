MODULE connect_loop_variable
! @format 2
! @section 4.15
! @expect semantic-error 8:15
! @description A loop variable is a read-only routine object, no connect target; refused at the target.
  PROC main()
    FOR i FROM 1 TO 2 DO
      CONNECT i WITH on_event;
    ENDFOR
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
