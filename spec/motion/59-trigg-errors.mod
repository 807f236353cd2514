MODULE trigg_errors
! @format 3
! @section 13
! @section 7
! @expect ok
! @statement-time 0
! @io io/trigg.io
! @description The errors of the instructions that define triggers (R-4.1-trigg4): a negative Distance, a digital value other than 0 or 1, or no output signal, ERR_ARGVALERR; a group value that is not a whole number, ERR_GO_LIM; an analog value beyond num's range, ERR_AO_LIM; a signal variable connected to no signal, ERR_NO_ALIASIO_DEF; TriggInt of an interrupt number not connected, ERR_UNKINO. A triggdata that nothing defined sets nothing, and the move goes on (R-4.1-trigg2); a trigger defined again after a Trigg move named it leaves that move's trigger as it was: do_gun changes, not do_aux.
! @output ERR_ARGVALERR
! @output ERR_ARGVALERR
! @output ERR_ARGVALERR
! @output ERR_GO_LIM
! @output ERR_AO_LIM
! @output ERR_NO_ALIASIO_DEF
! @output ERR_UNKINO
! @output at p2 TRUE
! @output do_gun 1 do_aux 0
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR signaldo do_local;
  VAR intnum never_connected;
  VAR dnum huge := 1E300;
  VAR triggdata t;
  VAR triggdata never_defined;
  PROC main()
    VAR robtarget here;
    MoveJ p1, v1000, fine, tool0;
    TriggIO t, -1 \DOp:=do_gun, 1;
    TriggIO t, 10 \DOp:=do_gun, 2;
    TriggIO t, 10, 1;
    TriggIO t, 10 \GOp:=go_code, 1.5;
    TriggIO t, 10 \AOp:=ao_flow, huge;
    TriggIO t, 10 \DOp:=do_local, 1;
    TriggInt t, 10, never_connected;
    TriggL p2, v1000, never_defined, fine, tool0;
    here := CRobT(\Tool:=tool0);
    TPWrite "at p2 " \Bool:=Distance(here.trans, p2.trans) < 0.01;
    TriggIO t, 50 \Start \DOp:=do_gun, 1;
    TriggL \Conc, p1, v100, t, fine, tool0;
    TriggIO t, 50 \Start \DOp:=do_aux, 1;
    WaitRob \InPos;
    TPWrite "do_gun " + NumToStr(do_gun, 0) + " do_aux " + NumToStr(do_aux, 0);
  ERROR
    TEST ERRNO
    CASE ERR_ARGVALERR:
      TPWrite "ERR_ARGVALERR";
    CASE ERR_GO_LIM:
      TPWrite "ERR_GO_LIM";
    CASE ERR_AO_LIM:
      TPWrite "ERR_AO_LIM";
    CASE ERR_NO_ALIASIO_DEF:
      TPWrite "ERR_NO_ALIASIO_DEF";
    CASE ERR_UNKINO:
      TPWrite "ERR_UNKINO";
    ENDTEST
    TRYNEXT;
  ENDPROC
ENDMODULE
