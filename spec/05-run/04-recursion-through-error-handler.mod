MODULE recursion_through_handler
! @format 3
! @section 5.4
! @section 7.1
! @section 1.4
! @expect ok
! @description Each call raises an error that its own handler takes, and the handler calls the routine again: the recursion has no end, and a resource limit (the depth of calls) stops it.
! @exit 3
  VAR num depth;
  PROC dive()
    depth := depth + 1;
    RAISE 1;
  ERROR
    dive;
  ENDPROC
  PROC main()
    dive;
  ENDPROC
ENDMODULE
