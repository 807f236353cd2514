MODULE orient_product
! @format 3
! @section 3.12
! @section 2.14
! @expect ok
! @description orient * orient links two rotations by the quaternion product, q1 being the scalar part (section 2.14): i * j = k, j * i = -k, and a half turn about z twice gives -1.
! @output ij=TRUE
! @output ji=TRUE
! @output kk=TRUE
! @exit 0
  PROC main()
    VAR orient i := [0, 1, 0, 0];
    VAR orient j := [0, 0, 1, 0];
    VAR orient k := [0, 0, 0, 1];
    TPWrite "ij=" \Bool:=i * j = [0, 0, 0, 1];
    TPWrite "ji=" \Bool:=j * i = [0, 0, 0, -1];
    TPWrite "kk=" \Bool:=k * k = [-1, 0, 0, 0];
  ENDPROC
ENDMODULE
