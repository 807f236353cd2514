MODULE connect_to_procedure
! @format 2
! @section 4.15
! @expect semantic-error 8:22
! @description CONNECT associates an interrupt with a trap routine; a procedure is refused at its name.
  VAR intnum ino;
  PROC main()
    CONNECT ino WITH handler;
  ENDPROC
  PROC handler()
  ENDPROC
ENDMODULE
