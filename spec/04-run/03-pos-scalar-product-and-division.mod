MODULE pos_scalar_product
! @format 3
! @section 3.12
! @expect ok
! @description num * pos, pos * num and pos / num scale every component (section 3.12).
! @output left=TRUE
! @output right=TRUE
! @output divided=TRUE
! @exit 0
  PROC main()
    VAR pos a := [1, -2, 3];
    VAR num k := 2;
    VAR pos b := [2, -4, 6];
    TPWrite "left=" \Bool:=k * a = [2, -4, 6];
    TPWrite "right=" \Bool:=a * k = [2, -4, 6];
    TPWrite "divided=" \Bool:=b / k = a;
  ENDPROC
ENDMODULE
