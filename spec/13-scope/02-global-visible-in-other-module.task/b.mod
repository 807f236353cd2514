MODULE cell
! @format 2
! @section 2.20
! @section 2.12
! @section 5.3
! @section 13
! @expect ok
! @description Global data, types and routines of one module are visible in the other modules of the task buffer.
  VAR gripdata grip := [10, 50];
  PROC main()
    speed_factor := 2;
    grip.force := scaled(grip.width);
    report "ready";
  ENDPROC
ENDMODULE
