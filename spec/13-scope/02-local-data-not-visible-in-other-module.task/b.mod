MODULE cell
! @format 2
! @section 2.20
! @section 13
! @expect semantic-error b.mod:9:10
! @description The scope of a LOCAL module data object is its module: another module does not see it; refused at the name.
  VAR num n;
  PROC main()
    n := secret;
  ENDPROC
ENDMODULE
