MODULE ui_client_exist
! @format 3
! @section 13
! @expect ok
! @options stub-unmodelled
! @description UIClientExist (ABB, RAPID Instructions: is a user device such as the FlexPendant connected to the controller) is FALSE: a run has nobody at the FlexPendant and no answers from one, with --stub-unmodelled too, so a program that asks first takes its branch without a dialogue (doc/rulings.md R-13-ui1).
! @output no pendant: Kraker
  PROC main()
    VAR btnres answer;
    IF UIClientExist() THEN
      answer := UIMessageBox(\Header:="Kraker" \Message:="Start?" \Buttons:=btnYesNo);
      TPWrite "asked";
    ELSE
      TPWrite "no pendant: Kraker";
    ENDIF
  ENDPROC
ENDMODULE
