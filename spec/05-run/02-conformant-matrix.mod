MODULE conformant_matrix
! @format 3
! @section 5.2
! @section 11
! @expect ok
! @description A parameter pallet{*,*} takes both dimensions from its argument; Dim(pallet, 1) and Dim(pallet, 2) give them (section 5.2, chapter 11).
! @output 14 x 18
! @output 2 x 3
! @exit 0
  VAR pos big{14, 18};
  VAR num small{2, 3};
  PROC size_pos(VAR pos pallet{*,*})
    TPWrite NumToStr(Dim(pallet, 1), 0) + " x " + NumToStr(Dim(pallet, 2), 0);
  ENDPROC
  PROC size_num(num m{*,*})
    TPWrite NumToStr(Dim(m, 1), 0) + " x " + NumToStr(Dim(m, 2), 0);
  ENDPROC
  PROC main()
    size_pos big;
    size_num small;
  ENDPROC
ENDMODULE
