MODULE octal_with_exponent
! @section 2.5
! @expect lexical-error 7:10
! @description Only decimal forms take an exponent: 0o17 touches the identifier E2.
  VAR num x;
  PROC main()
    x := 0o17E2;
  ENDPROC
ENDMODULE
