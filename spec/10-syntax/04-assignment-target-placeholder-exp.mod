MODULE assignment_target_placeholder_ex
! @section 4.5
! @expect syntax-error 7:5
! @description <assignment target> ::= <variable> | <persistent> | <parameter> | <VAR>: <EXP> is not one.
  VAR num x;
  PROC main()
    <EXP> := 1;
  ENDPROC
ENDMODULE
