MODULE rulings_array_sizes
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description R-3.12-e: = on two arrays whose sizes differ (possible only through {*} parameters) is the execution error ERR_NOTEQDIM; with no handler the task stops, and the error is reported where it occurred, at the RETURN in the function.
! @output same size=TRUE
! @exit 1
! @error ERR_NOTEQDIM 14:5
  VAR num two{2} := [1, 2];
  VAR num other{2} := [1, 2];
  VAR num three{3} := [1, 2, 3];
  FUNC bool same(num a{*}, num b{*})
    RETURN a = b;
  ENDFUNC

  PROC main()
    VAR bool r;
    TPWrite "same size=" \Bool:=same(two, other);
    r := same(two, three);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
