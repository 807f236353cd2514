MODULE placeholder_id_misplaced
! @section 2.9
! @expect syntax-error 8:12
! @description <ID> cannot stand for a component name (section 3.6).
  VAR pos p;
  VAR num x;
  PROC main()
    x := p.<ID>;
  ENDPROC
ENDMODULE
