MODULE bang_not_inequality
! @section 2.8
! @section 2.10
! @expect syntax-error 9:10
! @description "!" begins a comment, which may not stand inside an expression: "!=" is not an operator.
  VAR num a;
  VAR num b;
  PROC main()
    IF a != b THEN
      a := b;
    ENDIF
  ENDPROC
ENDMODULE
