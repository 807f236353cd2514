MODULE latin1_strings
  ! A Latin-1 file: cafי. Its strings hold bytes that are not UTF-8 and control characters.
  VAR string s := "caf\E9\0D\07x";
  PROC main()
    TPWrite s;
    TPWrite "\0A" + "יtי loסg";
    TPWrite "יייייייייייייייייייי" \Num:=StrLen("יייייייייייייייייייי");
  ENDPROC
ENDMODULE
