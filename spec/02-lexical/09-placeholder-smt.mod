MODULE placeholder_smt
! @section 2.9
! @section 4.1
! @section 4.17
! @expect ok
! @description <SMT> stands for a statement, also as the statement of a compact IF.
  VAR bool b;
  PROC main()
    <SMT>
    IF b <SMT>
    IF b THEN
      <SMT>
    ENDIF
  ENDPROC
ENDMODULE
