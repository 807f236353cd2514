MODULE compact_if_label
! @section 4.17
! @section 4.4
! @expect syntax-error 8:14
! @description A label is not a simple statement: it cannot be the statement of a compact IF.
  VAR bool b;
  PROC main()
    IF b next:
  ENDPROC
ENDMODULE
