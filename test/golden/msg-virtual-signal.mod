MODULE msg_virtual_signal
  PROC main()
    SetDO doGripper, 1;
    TPWrite "gripper closed";
  ENDPROC
ENDMODULE
