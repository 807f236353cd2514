MODULE bad_moves
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @max-time 100
! @description Bad move data is an error at the move, never a crash (doc/rulings.md R-4.1-e): a speed of 0 gives no time, a MoveC whose CirPoint is its start gives no circle (ERR_ARGVALERR), an orientation of 0 is not a normalised quaternion (ERR_ILLQUAT, installed-facts.md section 4: motion instructions check that quaternions are normalised); a move that would take 1E30 s runs into the bound of virtual time (exit 3).
! @output speed ERR_ARGVALERR
! @output circle ERR_ARGVALERR
! @output orient ERR_ILLQUAT
! @exit 3
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR speeddata s0 := [0, 0, 0, 0];
    VAR robtarget q;
    VAR string what := "speed";
    MoveJ p1, v1000, fine, tool0;
    MoveL Offs(p1, 0, 100, 0), s0, fine, tool0;
    what := "circle";
    MoveC p1, Offs(p1, 0, 100, 0), v100, fine, tool0;
    what := "orient";
    q := p1;
    q.rot := [0, 0, 0, 0];
    MoveL q, v100, fine, tool0;
    what := "time";
    MoveL Offs(p1, 0, 100, 0), v100 \T:=1E30, fine, tool0;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_ILLQUAT THEN
      TPWrite what + " ERR_ILLQUAT";
    ELSEIF ERRNO = ERR_ARGVALERR THEN
      TPWrite what + " ERR_ARGVALERR";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
