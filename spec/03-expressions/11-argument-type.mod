MODULE argument_type
! @format 2
! @section 3.11
! @expect semantic-error 8:19
! @description An argument's type must equal its parameter's; refused at the argument.
  VAR num x;
  PROC main()
    x := polar(1, "0.78");
  ENDPROC

  FUNC num polar(num dist, num angle)
    RETURN dist * angle;
  ENDFUNC
ENDMODULE
