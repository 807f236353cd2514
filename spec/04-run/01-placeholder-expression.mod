MODULE placeholder_expression
! @format 3
! @section 1.2
! @section 2.9
! @section 3.1
! @expect ok
! @description Evaluating the expression placeholder <EXP> raises ERR_EXECPHR at the statement that evaluates it (section 1.2, chapter 12).
! @exit 1
! @error ERR_EXECPHR 12:5
  PROC main()
    VAR num x;
    x := <EXP>;
    TPWrite "after";
  ENDPROC
ENDMODULE
