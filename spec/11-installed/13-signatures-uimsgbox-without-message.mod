MODULE sig_uimsgbox_without
! @format 2
! @section 4.6
! @section 13
! @expect semantic-error 9:5
! @description UIMsgBox has one required argument, MsgLine1 (ABB: UIMsgBox [\Header] MsgLine1 [\MsgLine2] ...): a call with only \Header is refused at the call.
  PROC main()
    UIMsgBox \Header:="Cell", "ready";
    UIMsgBox \Header:="Cell";
  ENDPROC
ENDMODULE
