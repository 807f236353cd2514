MODULE placeholder_letter_case
! @section 2.9
! @expect ok
! @description Placeholders are recognised in any letter case, like reserved words.
  <tdn>
  <Ddn>
  PROC main()
    <smt>
    <Var> := 1;
  ENDPROC
  <rdN>
ENDMODULE
