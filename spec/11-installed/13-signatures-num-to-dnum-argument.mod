MODULE sig_num_to_dnum
! @format 2
! @section 5.2
! @section 2.17
! @expect semantic-error 12:33
! @description A num variable given for a dnum parameter (BitCheckDnum's Value, ABB's RAPID reference) is refused: num and dnum are two types (§2.13, §2.17) and ABB converts with NumToDnum, as in the line before (doc/rulings.md R-5.2-sys7). A numeric literal takes dnum from the parameter (R-2.5-b).
  VAR num n := 5;
  VAR bool set;
  PROC main()
    set := BitCheckDnum(NumToDnum(n), 1);
    set := BitCheckDnum(5, 1);
    set := set AND BitCheckDnum(n, 1);
  ENDPROC
ENDMODULE
