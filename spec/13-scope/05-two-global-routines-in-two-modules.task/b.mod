MODULE cell
! @format 2
! @section 5.3
! @expect semantic-error b.mod:6:13
! @description Two global routines in different modules may not share a name; refused at the one in the later file.
  FUNC bool init()
    RETURN TRUE;
  ENDFUNC
ENDMODULE
