MODULE operator_dialogues
! @format 3
! @section 13
! @expect ok
! @operator 13-operator-dialogues.operator
! @description Under --operator the FlexPendant's dialogues take the script's answers in order (doc/rulings.md R-13-ui2): TPReadFK the key's number, given by number or by its text, and its text written on the operator window as TPWrite's; TPReadNum the number; UIMsgBox's \Result and UIMessageBox's value the button's btnres, or a \BtnArray button's index; UINumEntry and UINumTune the number, UIAlphaEntry the text, UIListView the item's index with the button in \Result. UIClientExist is TRUE.
! @output client TRUE
! @output Go on?
! @output key 2
! @output Again?
! @output key 1
! @output Count?
! @output count 12.5
! @output box 7
! @output message 3
! @output array 2
! @output entry 7
! @output text P10 "top"
! @output item 2
! @output 1
! @output tune 3.5
  PROC main()
    VAR num key;
    VAR btnres answer;
    VAR num n;
    VAR string s;
    VAR listitem items{3} := [["", "Weld"], ["", "Grind"], ["", "Home"]];
    TPWrite "client " \Bool:=UIClientExist();
    TPReadFK key, "Go on?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "key " \Num:=key;
    TPReadFK key, "Again?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "key " \Num:=key;
    TPReadNum n, "Count?";
    TPWrite "count " \Num:=n;
    UIMsgBox \Header:="Cell", "Start?" \Buttons:=btnYesNo \Result:=answer;
    TPWrite "box " \Num:=answer;
    answer := UIMessageBox(\Message:="Failed" \Buttons:=btnRetryCancel);
    TPWrite "message " \Num:=answer;
    answer := UIMessageBox(\Message:="Part?" \BtnArray:=["Take", "Skip", "", "", ""]);
    TPWrite "array " \Num:=answer;
    n := UINumEntry(\Message:="Parts" \InitValue:=1 \MinValue:=1 \MaxValue:=10 \AsInteger);
    TPWrite "entry " \Num:=n;
    s := UIAlphaEntry(\Message:="Target");
    TPWrite "text " + s;
    n := UIListView(\Result:=answer \Header:="Job", items \Buttons:=btnOKCancel);
    TPWrite "item " \Num:=n;
    TPWrite "" \Num:=answer;
    n := UINumTune(\Message:="Offset", 3, 0.5 \MinValue:=0 \MaxValue:=5);
    TPWrite "tune " \Num:=n;
  ENDPROC
ENDMODULE
