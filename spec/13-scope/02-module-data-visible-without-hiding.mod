MODULE module_data_visible_without
! @format 2
! @section 2.20
! @section 2.17
! @expect semantic-error 10:14
! @description Without a routine object of that name, level is the module's string: assigning 3 is refused at the right-hand side.
  VAR string level;
  PROC main()
    VAR num count;
    level := 3;
  ENDPROC
ENDMODULE
