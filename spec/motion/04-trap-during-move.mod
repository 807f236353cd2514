MODULE trap_during_move
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description Interrupts are served while the program pointer waits for a move (ch. 8: during waits); a trap taken 2.5 s into a 500 mm MoveL at v100 reads CRobT halfway, at y = 0 (I-interp). The move still ends at 5 s.
! @output trap at 2500 y 0
! @output end 5000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum tick;
  TRAP halfway
    VAR robtarget here;
    here := CRobT(\Tool:=tool0);
    TPWrite "trap at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(Abs(here.trans.y), 0);
  ENDTRAP
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    CONNECT tick WITH halfway;
    ITimer \Single, 2.5, tick;
    MoveL p2, v100, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
    IDelete tick;
  ENDPROC
ENDMODULE
