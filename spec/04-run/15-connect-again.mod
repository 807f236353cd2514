MODULE connect_again
! @format 3
! @section 4.15
! @section 12
! @expect ok
! @description CONNECT gives its target an interrupt number, which cannot be connected again (section 4.15: the same connect statement cannot be executed more than once): the second CONNECT of hp raises ERR_ALRDYCNT (chapter 12).
! @output connected
! @exit 1
! @error ERR_ALRDYCNT 14:5
  VAR intnum hp;
  PROC main()
    CONNECT hp WITH high_pressure;
    TPWrite "connected";
    CONNECT hp WITH high_pressure;
    TPWrite "wrong";
  ENDPROC
  TRAP high_pressure
    TPWrite "trap";
  ENDTRAP
ENDMODULE
