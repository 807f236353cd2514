MODULE not_modelled
  ! EGMGetId (Externally Guided Motion) is installed, and rapid-sem does not model EGM.
  VAR egmident egm1;
  PROC main()
    TPWrite "before";
    EGMGetId egm1;
    TPWrite "after";
  ENDPROC
ENDMODULE
