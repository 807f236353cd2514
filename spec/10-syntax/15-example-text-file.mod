MODULE write_from_file
! @section 15
! @expect ok
! @description The module write_from_file.mod of chapter 15.
 VAR num text_res_no;
VAR string text1;
PROC main()
 IF TextTabFreeToUse("ACTION_TXRES") THEN
  TextTabInstall "HOME:/text_file.xml";
 ENDIF
 text_res_no := TextTabGet("ACTION_TXRES");
 text1 := TextGet(text_res_no, 2);
 TPWrite text1; ! The word "Stop" will be printed.
 ENDPROC
 ENDMODULE
