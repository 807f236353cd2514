MODULE for_loop_variable_hides
! @format 3
! @section 4.18
! @expect ok
! @description The loop variable is a new num object with the statement list as its scope and hides an object of the same name (section 4.18): the module variable i is untouched by the loop.
! @output inside 1
! @output inside 2
! @output outside 42
! @exit 0
  VAR num i := 42;
  PROC main()
    FOR i FROM 1 TO 2 DO
      TPWrite "inside " \Num:=i;
    ENDFOR
    TPWrite "outside " \Num:=i;
  ENDPROC
ENDMODULE
