MODULE connect_string_target
! @format 2
! @section 4.15
! @expect semantic-error 8:13
! @description The target must be of type num or an alias of num; a string variable is refused at the target.
  VAR string name;
  PROC main()
    CONNECT name WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
