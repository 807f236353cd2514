MODULE ext_calc
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot robot/track.robot
! @description CalcJointT and CalcRobT with a track (doc/motion.md X-position): a robtarget's position is in the world and its eax_a places the base, so [802,0,558] pointing down with eax_a 500 is the arm's axis 5 at 90 (its home, 302 from the base), and the jointtarget carries the robtarget's external axes; a 9E9 track component means the track where it stands now (0 here), so [902,0,558] is out of the arm's reach of the base at 0 (ERR_ROBLIMIT, stored by \ErrorNumber); CalcRobT of the home axes with eax_a 1000 is [1302,0,558] in the world, its extax the jointtarget's.
! @output jt rax_5 90.0 eax_a 500.0 eax_b TRUE
! @output err TRUE
! @output rt x 1302.0 z 558.0 eax_a 1000.0
  CONST robtarget p1 := [[802,0,558],[0,0,1,0],[0,0,0,0],[500,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[902,0,558],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget j1 := [[0,0,0,0,90,0],[1000,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR jointtarget j;
    VAR robtarget r;
    VAR errnum e;
    j := CalcJointT(p1, tool0);
    TPWrite "jt rax_5 " + NumToStr(j.robax.rax_5, 1) + " eax_a " + NumToStr(j.extax.eax_a, 1) + " eax_b " \Bool:=(j.extax.eax_b = 9E9);
    j := CalcJointT(p2, tool0 \ErrorNumber:=e);
    TPWrite "err " \Bool:=(e = ERR_ROBLIMIT);
    r := CalcRobT(j1, tool0);
    TPWrite "rt x " + NumToStr(r.trans.x, 1) + " z " + NumToStr(r.trans.z, 1) + " eax_a " + NumToStr(r.extax.eax_a, 1);
  ENDPROC
ENDMODULE
