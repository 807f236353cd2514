MODULE refused_string_comparison
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description < takes num or dnum operands; strings are refused at the left operand.
  VAR string s1;
  VAR string s2;
  VAR bool r;
  PROC main()
    r := s1 < s2;
  ENDPROC
ENDMODULE
