MODULE sig_open_read
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 10:35
! @description Open: \Read, \Write and \Append are alternatives (ABB: [\Read] | [\Write] | [\Append] [\Bin]); giving two is refused at the second's backslash, while \Bin combines with any of them.
  VAR iodev log;
  PROC main()
    Open "HOME:/a.bin", log \Read \Bin;
    Open "HOME:/a.txt", log \Read \Write;
  ENDPROC
ENDMODULE
