MODULE installed_b
! @task T_B
  PROC main()
    WaitTime 0.1;
    TPWrite "B mass " \Num := load0.mass;
    TPWrite "B ERRNO " \Num := ERRNO;
  ENDPROC
ENDMODULE
