MODULE test_placeholders
! @format 2
! @section 4.20
! @section 2.9
! @expect ok
! @description <CSE>, <EXP>, <SMT> and <EIT> stand in statements without a semantic error.
  VAR num n;
  PROC main()
    TEST n
    CASE 1:
      <SMT>
    <CSE>
    ENDTEST
    IF <EXP> THEN
      n := <EXP>;
    <EIT>
    ENDIF
  ENDPROC
ENDMODULE
