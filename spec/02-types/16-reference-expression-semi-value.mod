MODULE reference_expression_semi_value
! @format 2
! @section 2.16
! @section 2.17
! @expect ok
! @description Table of section 2.16, row object used in an expression, column semi-value: legal with the associated type (section 2.16's IF sig1 = 1).
  VAR signaldi sig1;
  VAR num n;
  PROC main()
    IF sig1 = 1 THEN
      n := sig1 + 1;
    ENDIF
    WHILE sig1 <> 0 DO
      n := n * sig1;
    ENDWHILE
  ENDPROC
ENDMODULE
