MODULE My_Module(NOSTEPIN)
! @section 9.4
! @expect ok
! @description The example of section 9.4.
PROC MoveSquare(robtarget pos1, robtarget pos2, robtarget pos3)
MoveJ pos1,v500,fine,tool0;
!Now you can modify the first position pos1
MoveJ pos2, v500, fine, tool0;
!Now you can modify the second position pos2
MoveJ pos3,v500,fine,tool0;
!The third and last position pos3 can be modified when the whole procedure has been run
ENDPROC
ENDMODULE
