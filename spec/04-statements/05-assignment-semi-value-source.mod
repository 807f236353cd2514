MODULE assignment_semi_value_source
! @format 2
! @section 4.5
! @section 2.16
! @expect ok
! @description A semi-value object on the right-hand side is in value context: it gives its associated num.
  VAR signaldi di1;
  VAR num level;
  PROC main()
    level := di1;
    level := di1 * 10;
  ENDPROC
ENDMODULE
