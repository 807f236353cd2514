MODULE stationary_tool
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description A stationary tool (robhold FALSE, its TCP fixed at [450,0,250] in the world) and a work object the robot carries (robhold TRUE, uframe 60 mm along the flange's z, oframe 20 mm along x): the flange is at tframe (W target)^-1 (F-frames). W is a translation by [20,0,60], so pa = [-150,0,90] pointing down puts the flange at [450,0,250] - [130,0,-150] = [320,0,400]; MoveL to Offs(pa,0,-50,0) moves the fixed TCP 50 mm on a straight line in the work object at v100: 0.5 s (T-cartesian, R-4.1-o), and the flange to [320,50,400]. CPos with the stationary tool and the work object reads the target; with tool0 in wobj0, the flange.
! @output t 500
! @output in the work object -150 -50 90
! @output flange 320 50 400
  PERS tooldata fixed_tool := [FALSE,[[450,0,250],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata held := [TRUE,TRUE,"",[[0,0,60],[1,0,0,0]],[[20,0,0],[1,0,0,0]]];
  CONST robtarget pa := [[-150,0,90],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos p;
    MoveJ pa, v1000, fine, fixed_tool \WObj:=held;
    ClkStart clk;
    MoveL Offs(pa, 0, -50, 0), v100, fine, fixed_tool \WObj:=held;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    p := CPos(\Tool:=fixed_tool \WObj:=held);
    TPWrite "in the work object " + NumToStr(p.x, 0) + " " + NumToStr(p.y, 0) + " " + NumToStr(p.z, 0);
    p := CPos(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "flange " + NumToStr(p.x, 0) + " " + NumToStr(p.y, 0) + " " + NumToStr(p.z, 0);
  ENDPROC
ENDMODULE
