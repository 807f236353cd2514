MODULE not_modelled
  ! EGMStreamStop (EGM position streaming) is installed, and rapid-sem does not model it.
  VAR egmident egm1;
  PROC main()
    TPWrite "before";
    EGMStreamStop egm1;
    TPWrite "after";
  ENDPROC
ENDMODULE
