MODULE connect_num_target
! @format 2
! @section 4.15
! @expect ok
! @description The target may be of type num itself, or an alias of num.
  ALIAS num signal_no;
  VAR num plain;
  VAR signal_no aliased;
  PROC main()
    CONNECT plain WITH on_event;
    CONNECT aliased WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
