MODULE missing_required_argument
! @format 2
! @section 3.11
! @expect semantic-error 8:10
! @description A required argument may not be left out; refused at the function name.
  VAR num x;
  PROC main()
    x := polar(3.937);
  ENDPROC

  FUNC num polar(num dist, num angle)
    RETURN dist * angle;
  ENDFUNC
ENDMODULE
