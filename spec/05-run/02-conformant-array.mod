MODULE conformant_array
! @format 3
! @section 5.2
! @section 5.4
! @expect ok
! @description Section 5.4's arrmul: a var parameter num array{*} takes its dimension from the argument (found with Dim) and is an alias of it, so every element of the caller's array is multiplied.
! @output 3 6 9 12
! @output 10 20
! @exit 0
  VAR num four{4} := [1, 2, 3, 4];
  VAR num two{2} := [1, 2];
  PROC arrmul(VAR num array{*}, num factor)
    FOR index FROM 1 TO Dim(array, 1) DO
      array{index} := array{index} * factor;
    ENDFOR
  ENDPROC
  PROC main()
    arrmul four, 3;
    arrmul two, 10;
    TPWrite NumToStr(four{1}, 0) + " " + NumToStr(four{2}, 0) + " " + NumToStr(four{3}, 0) + " " + NumToStr(four{4}, 0);
    TPWrite NumToStr(two{1}, 0) + " " + NumToStr(two{2}, 0);
  ENDPROC
ENDMODULE
