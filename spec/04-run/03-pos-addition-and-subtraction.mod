MODULE pos_addition_and_subtraction
! @format 3
! @section 3.12
! @expect ok
! @description Vector addition and subtraction of pos values, component by component, and the unary signs on pos (section 3.12).
! @output sum=TRUE
! @output difference=TRUE
! @output negated=TRUE
! @output plus=TRUE
! @exit 0
  PROC main()
    VAR pos a := [1, 2, 3];
    VAR pos b := [4, 6, 8];
    TPWrite "sum=" \Bool:=a + b = [5, 8, 11];
    TPWrite "difference=" \Bool:=b - a = [3, 4, 5];
    TPWrite "negated=" \Bool:=-a = [-1, -2, -3];
    TPWrite "plus=" \Bool:=+a = [1, 2, 3];
  ENDPROC
ENDMODULE
