MODULE named_argument_unknown
! @format 2
! @section 3.11
! @expect semantic-error 8:29
! @description A named argument must name a parameter: scaled has no parameter factour (its optional factor is given with a backslash); refused at the argument.
  VAR num x;
  PROC main()
    x := scaled(value := 1, factour := 2);
  ENDPROC
  FUNC num scaled(num value \num factor)
    IF Present(factor) RETURN value * factor;
    RETURN value;
  ENDFUNC
ENDMODULE
