MODULE aggregate_as_argument
! @format 2
! @section 3.10
! @section 3.11
! @expect ok
! @description The parameter's type determines an argument aggregate's type (user routine, installed TPWrite \Pos).
  VAR num d;
  PROC goto_point(pos target)
  ENDPROC
  FUNC num length(pos v)
    RETURN v.x + v.y + v.z;
  ENDFUNC
  PROC main()
    goto_point [1, 2, 3];
    d := length([3, 4, 0]);
    TPWrite "p" \Pos:=[1, 2, 3];
  ENDPROC
ENDMODULE
