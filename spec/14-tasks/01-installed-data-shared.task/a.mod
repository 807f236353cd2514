MODULE installed_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description ch. 14: installed data objects share their values between the tasks, except the installed system variables ERRNO and INTNO, whose values are each task's (R-14-g): B sees A's write to load0, and not A's ERRNO.
! @output A ERRNO 1007
! @output B mass 2
! @output B ERRNO 0
  PROC main()
    VAR num x;
    load0.mass := 2;
    x := 1 / 0;
  ERROR
    TPWrite "A ERRNO " \Num := ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
