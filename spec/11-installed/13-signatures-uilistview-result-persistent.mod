MODULE sig_uilistview_result
! @format 2
! @section 5.2
! @expect ok
! @description UIListView's and UIMsgBox's \Result (ABB's RAPID reference: "var or pers (INOUT) of btnres") take a variable or a persistent.
  PERS btnres lastAnswer := 0;
  VAR btnres answer;
  VAR num choice;
  CONST listitem items{2} := [["", "Run"], ["", "Stop"]];
  PROC main()
    choice := UIListView(\Result:=lastAnswer \Header:="Menu", items \Buttons:=btnOKCancel);
    choice := UIListView(\Result:=answer, items);
    UIMsgBox "Ready?" \Buttons:=btnYesNo \Result:=lastAnswer;
    UIMsgBox "Ready?" \Result:=answer;
  ENDPROC
ENDMODULE
