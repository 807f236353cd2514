MODULE deadlock
  PROC main()
    TPWrite "waiting for the part";
    WaitDI di_part, 1;
  ENDPROC
ENDMODULE
