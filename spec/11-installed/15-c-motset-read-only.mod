MODULE c_motset_read_only
! @format 2
! @section 4.5
! @section 11
! @section 12
! @expect semantic-error 9:5
! @description C_MOTSET is changed by the motion settings instructions only (ABB, motsetdata), read-only as ERRNO (chapter 12): an assignment to one of its components is refused at the target (doc/rulings.md R-13-motset1).
  PROC main()
    C_MOTSET.vel.oride := 50;
  ENDPROC
ENDMODULE
