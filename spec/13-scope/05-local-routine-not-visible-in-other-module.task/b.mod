MODULE cell
! @format 2
! @section 5.3
! @section 13
! @expect semantic-error b.mod:8:5
! @description The scope of a LOCAL routine is its module; a call from another module is refused at the name.
  PROC main()
    init;
  ENDPROC
ENDMODULE
