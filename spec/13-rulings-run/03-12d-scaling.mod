MODULE rulings_pos_scaling
! @format 3
! @section 3.12
! @expect ok
! @description R-3.12-d: num * pos, pos * num and pos / num scale each component, and each component is rounded once to single precision: [1,2,3] / 10 equals the pos [0.1,0.2,0.3] written with literals.
! @output 2*[1,2,3]=[2,4,6]
! @output [1,2,3]*-2=[-2,-4,-6]
! @output [2,4,6]/2=[1,2,3]
! @output [1,2,3]/10=[0.1,0.2,0.3] TRUE
! @exit 0
  PROC main()
    VAR pos a := [1, 2, 3];
    VAR pos b := [2, 4, 6];
    VAR pos tenth := [0.1, 0.2, 0.3];
    VAR num ten := 10;
    TPWrite "2*[1,2,3]=" \Pos:=2 * a;
    TPWrite "[1,2,3]*-2=" \Pos:=a * (-2);
    TPWrite "[2,4,6]/2=" \Pos:=b / 2;
    TPWrite "[1,2,3]/10=[0.1,0.2,0.3] " \Bool:=a / ten = tenth;
  ENDPROC
ENDMODULE
