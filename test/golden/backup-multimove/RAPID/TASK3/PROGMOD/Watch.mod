MODULE Watch
  ! A task without a robot, in the mechanical unit group rob2: CJointT() reads T_ROB2's robot,
  ! \TaskName the other one's.
  PROC main()
    VAR jointtarget mine;
    VAR jointtarget other;
    WaitTime 2;
    mine := CJointT();
    other := CJointT(\TaskName:="T_ROB1");
    TPWrite "watch: my group's axis 1 " \Num:=Round(mine.robax.rax_1);
    TPWrite "watch: T_ROB1's axis 1 " \Num:=Round(other.robax.rax_1);
  ENDPROC
ENDMODULE
