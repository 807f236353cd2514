MODULE too_many_arguments
! @format 2
! @section 3.11
! @expect semantic-error 8:22
! @description A call with more arguments than parameters; refused at the first argument too many.
  VAR num x;
  PROC main()
    x := polar(1, 2, 3);
  ENDPROC

  FUNC num polar(num dist, num angle)
    RETURN dist * angle;
  ENDFUNC
ENDMODULE
