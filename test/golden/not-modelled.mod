MODULE not_modelled
  ! MoveExtJ moves external axes only, which the motion model leaves out (doc/motion.md).
  CONST jointtarget j1 := [[9E9,9E9,9E9,9E9,9E9,9E9],[90,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "before";
    MoveExtJ j1, vrot50, fine;
    TPWrite "after";
  ENDPROC
ENDMODULE
