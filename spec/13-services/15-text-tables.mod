MODULE text_tables
! @format 3
! @section 15
! @expect ok
! @home home
! @description Text tables are numbered in the order they are installed; TextTabFreeToUse is FALSE once a table of the name is installed, and installing a second file with that name changes nothing; an ISO-8859-1 file's texts come as UTF-8 with their spaces; a table or index that does not exist raises ERR_TXTNOEXIST; a file that does not exist, or is not a text resource, ERR_FILEACC.
! @output free TRUE
! @output free FALSE
! @output numbers 1 2
! @output Call_service_man
! @output Grüße
! @output [  spaces kept  ]
! @output still Stop
! @output ERR_TXTNOEXIST
! @output ERR_TXTNOEXIST
! @output ERR_TXTNOEXIST
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @exit 0
  VAR num first;
  VAR num second;
  PROC main()
    TPWrite "free " \Bool:=TextTabFreeToUse("ACTION_TXRES");
    TextTabInstall "HOME:/text_file.xml";
    TextTabInstall "HOME:/german.xml";
    TPWrite "free " \Bool:=TextTabFreeToUse("ACTION_TXRES");
    first := TextTabGet("ACTION_TXRES");
    second := TextTabGet("GERMAN");
    TPWrite "numbers " + ValToStr(first) + " " + ValToStr(second);
    TPWrite TextGet(first, 4);
    TPWrite TextGet(second, 1);
    TPWrite "[" + TextGet(second, 2) + "]";
    TextTabInstall "HOME:/again.xml";
    TPWrite "still " + TextGet(TextTabGet("ACTION_TXRES"), 2);
    TPWrite Attempt(1);
    TPWrite Attempt(2);
    TPWrite Attempt(3);
    TPWrite Attempt(4);
    TPWrite Attempt(5);
    TPWrite Attempt(6);
  ENDPROC

  FUNC string Attempt(num what)
    VAR num n;
    VAR string s;
    TEST what
    CASE 1:
      n := TextTabGet("NO_SUCH_TABLE");
    CASE 2:
      s := TextGet(TextTabGet("GERMAN"), 3);
    CASE 3:
      s := TextGet(7, 1);
    CASE 4:
      TextTabInstall "HOME:/missing.xml";
    CASE 5:
      TextTabInstall "HOME:/broken.xml";
    CASE 6:
      TextTabInstall "HOME:/../../text_file.xml";
    ENDTEST
    RETURN "no error";
  ERROR
    IF ERRNO = ERR_TXTNOEXIST RETURN "ERR_TXTNOEXIST";
    IF ERRNO = ERR_FILEACC RETURN "ERR_FILEACC";
  ENDFUNC
ENDMODULE
