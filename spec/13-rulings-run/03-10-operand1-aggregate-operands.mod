MODULE aggregate_operands
! @format 3
! @section 3.10
! @section 3.12
! @expect ok
! @description Ruling R-3.10-operand1: an aggregate operand takes the type the operator table leaves it beside the other operand, and the operator is that row's: the quaternion product with an orient, vector addition and the cross product with a pos, scaling with a num.
! @output rot=[0,0,0,1]
! @output sum=[2,4,6]
! @output cross=[0,-3,2]
! @output scaled=[2,4,6]
! @output divided=[1,2,3]
! @output chain=[0.5,1.5,2.5]
! @exit 0
  VAR pose p := [[1, 2, 3], [1, 0, 0, 0]];
  PROC main()
    TPWrite "rot=" \Orient:=p.rot * [0, 0, 0, 1];
    TPWrite "sum=" \Pos:=p.trans + [1, 2, 3];
    TPWrite "cross=" \Pos:=[1, 0, 0] * p.trans;
    TPWrite "scaled=" \Pos:=2 * [1, 2, 3];
    TPWrite "divided=" \Pos:=[3, 6, 9] / 3;
    TPWrite "chain=" \Pos:=p.trans - [1, 1, 1] + [0.5, 0.5, 0.5];
  ENDPROC
ENDMODULE
