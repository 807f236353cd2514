MODULE constant_div_beyond_integers
! @format 2
! @section 3.2
! @section 3.12
! @section 2.13
! @expect semantic-error 11:18
! @description 16777216 is a whole number, but beyond the integers a num represents exactly (-8388607..8388608, §2.13); as an operand of DIV (§3.12 note b) it fails (ERR_MAXINTVAL, doc/rulings.md R-3.12-b), in a routine variable's initial value: known before the program runs.
  CONST num big := 16777216;
  PROC main()
    VAR num n := 7;
    VAR num q := big DIV 2;
    n := q;
  ENDPROC
ENDMODULE
