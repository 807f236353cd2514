MODULE index_not_integer
! @format 3
! @section 3.6
! @section 12
! @expect ok
! @description An index must represent an integer value greater than 0 (section 3.6): a{i} with i = 1.5 raises ERR_NOTINTVAL ("not an integer value", chapter 12) at the statement that evaluates it (doc/rulings.md R-3.6).
! @exit 1
! @error ERR_NOTINTVAL 13:5
  VAR num a{3} := [1, 2, 3];
  PROC main()
    VAR num i := 1.5;
    VAR num x;
    x := a{i};
  ENDPROC
ENDMODULE
