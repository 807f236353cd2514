MODULE long_jump_cancels_move
! @format 3
! @section 7.2
! @expect ok
! @statement-time 0
! @description Error recovery across execution levels (section 7.2): a trap raises error 56 two seconds into a 5 s MoveL; the long jump goes to main's error recovery point, and the move instruction active at normal level is cancelled with the rest of its path ("an active Movex instruction clears part of its path"): the robot stands where it was at 2 s (y = -50) and after a 1 s wait the next move starts from there: back to p1, 200 mm at v100, from 3 s to 5 s.
! @output recovered at 2000 y -50
! @output still y -50
! @output back at 5000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum tick;
  TRAP alarm
    RAISE 56;
  ENDTRAP
  PROC main()
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    CONNECT tick WITH alarm;
    ITimer \Single, 2, tick;
    MoveL p2, v100, fine, tool0;
    TPWrite "not reached";
  ERROR (56)
    p := CPos(\Tool:=tool0);
    TPWrite "recovered at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(p.y, 0);
    WaitTime 1;
    p := CPos(\Tool:=tool0);
    TPWrite "still y " \Num:=Round(p.y);
    MoveL p1, v100, fine, tool0;
    TPWrite "back at " \Num:=Round(1000 * ClkRead(clk));
    IDelete tick;
    RETURN;
  ENDPROC
ENDMODULE
