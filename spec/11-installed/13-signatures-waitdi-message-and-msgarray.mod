MODULE sig_waitdi_message
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 10:54
! @description WaitDI: \Message and \MsgArray are alternatives (ABB: [\Message] | [\MsgArray]); giving both is refused at the second's backslash.
  VAR signaldi diReady;
  CONST string lines{2} := ["a", "b"];
  PROC main()
    WaitDI diReady, 1 \Visualize \Message:="Waiting" \MsgArray:=lines;
  ENDPROC
ENDMODULE
