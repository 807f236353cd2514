MODULE tpwrite_orient
! @format 3
! @section 13
! @expect ok
! @description TPWrite \Orient writes the quaternion as an aggregate [q1,q2,q3,q4], without spaces; the components here are integers.
! @output o=[1,0,0,0]
! @output o=[0,0,-1,0]
! @exit 0
  PROC main()
    VAR orient o := [1, 0, 0, 0];
    TPWrite "o=" \Orient:=o;
    o := [0, 0, -1, 0];
    TPWrite "o=" \Orient:=o;
  ENDPROC
ENDMODULE
