MODULE rulings_array_comparison
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description R-3.12-e: arrays compare element by element, numbers by IEEE equality (0 = -0); = and <> on arrays of different sizes, in one dimension or in an inner one, are ERR_NOTEQDIM.
! @output equal=TRUE
! @output 0 = -0 TRUE
! @output differ=TRUE
! @output = sizes 2 and 3: ERR_NOTEQDIM
! @output <> sizes 2 and 3: ERR_NOTEQDIM
! @output <> sizes 1x2 and 1x3: ERR_NOTEQDIM
! @exit 0
  VAR num two{2} := [1, 2];
  VAR num other{2} := [1, 2];
  VAR num three{3} := [1, 2, 3];
  VAR num m12{1, 2} := [[1, 2]];
  VAR num m13{1, 3} := [[1, 2, 3]];
  VAR string what;

  FUNC bool eq(num a{*}, num b{*})
    RETURN a = b;
  ENDFUNC

  FUNC bool ne(num a{*}, num b{*})
    RETURN a <> b;
  ENDFUNC

  FUNC bool ne2(num a{*,*}, num b{*,*})
    RETURN a <> b;
  ENDFUNC

  PROC main()
    VAR num zeros{2} := [0, 1];
    VAR num negzeros{2} := [0, 1];
    TPWrite "equal=" \Bool:=eq(two, other);
    negzeros{1} := -zeros{1};
    TPWrite "0 = -0 " \Bool:=eq(zeros, negzeros);
    other{2} := 3;
    TPWrite "differ=" \Bool:=ne(two, other);
    what := "= sizes 2 and 3";
    TPWrite "equal=" \Bool:=eq(two, three);
    what := "<> sizes 2 and 3";
    TPWrite "differ=" \Bool:=ne(two, three);
    what := "<> sizes 1x2 and 1x3";
    TPWrite "differ=" \Bool:=ne2(m12, m13);
  ERROR
    IF ERRNO = ERR_NOTEQDIM THEN
      TPWrite what + ": ERR_NOTEQDIM";
    ELSE
      TPWrite what + ": another error";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
