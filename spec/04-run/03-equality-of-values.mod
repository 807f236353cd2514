MODULE equality_of_values
! @format 3
! @section 3.12
! @expect ok
! @description = and <> compare any value type, records component by component and arrays element by element (section 3.12); strings compare their characters.
! @output records equal=TRUE
! @output records differ=TRUE
! @output arrays equal=TRUE
! @output arrays differ=TRUE
! @output strings=FALSE
! @output bools=TRUE
! @exit 0
  VAR pose p1 := [[1, 2, 3], [1, 0, 0, 0]];
  VAR pose p2 := [[1, 2, 3], [1, 0, 0, 0]];
  VAR num a{3} := [1, 2, 3];
  VAR num b{3} := [1, 2, 3];
  PROC main()
    TPWrite "records equal=" \Bool:=p1 = p2;
    p2.rot.q4 := 1;
    TPWrite "records differ=" \Bool:=p1 <> p2;
    TPWrite "arrays equal=" \Bool:=a = b;
    b{3} := 4;
    TPWrite "arrays differ=" \Bool:=a <> b;
    TPWrite "strings=" \Bool:="abc" = "abC";
    TPWrite "bools=" \Bool:=TRUE <> FALSE;
  ENDPROC
ENDMODULE
