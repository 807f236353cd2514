MODULE sig_socketreceive_str
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 9:26
! @description SocketReceive \Str stores the received string: its argument must be a variable, a literal is refused.
  VAR socketdev client;
  PROC main()
    SocketReceive client \Str:="text";
  ENDPROC
ENDMODULE
