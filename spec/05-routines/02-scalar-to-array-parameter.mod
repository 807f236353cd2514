MODULE scalar_to_array_parameter
! @format 2
! @section 5.2
! @expect semantic-error 10:12
! @description A scalar argument for an array parameter; refused at the argument.
  VAR num n;
  PROC arrmul(VAR num array{*}, num factor)
  ENDPROC
  PROC main()
    arrmul n, 2;
  ENDPROC
ENDMODULE
