MODULE connect_unknown_trap
! @format 2
! @section 4.15
! @expect semantic-error 8:22
! @description A trap that is not declared; refused at its name.
  VAR intnum ino;
  PROC main()
    CONNECT ino WITH nosuch_trap;
  ENDPROC
ENDMODULE
