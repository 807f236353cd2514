MODULE motionsup_accepted
! @format 3
! @section 11
! @expect ok
! @description MotionSup (ABB, RAPID Instructions: collision detection on or off, \TuneValue its sensitivity in percent) is installed and accepted with each of its forms; the motion model has no dynamics, so it detects no collision and the call changes nothing (doc/rulings.md R-13-motset1).
! @output done
  PROC main()
    MotionSup \Off;
    MotionSup \On \TuneValue:=200;
    MotionSup;
    TPWrite "done";
  ENDPROC
ENDMODULE
