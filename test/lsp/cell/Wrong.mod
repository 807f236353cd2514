MODULE Wrong
  PROC Broken()
    VAR num n;
    n := "text";
    TPWrite "Grüße 😀"; n := TRUE;
    Pick 5;
  ENDPROC
ENDMODULE
