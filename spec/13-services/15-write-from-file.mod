MODULE write_from_file
! @format 3
! @section 15
! @expect ok
! @home home
! @description The manual's example of chapter 15 (write_from_file.mod and text_file.xml): TextTabFreeToUse, TextTabInstall, TextTabGet and TextGet print "Stop". The file's Resource Name is the table name the program uses (doc/rulings.md R-15-a).
! @output Stop
! @exit 0
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
