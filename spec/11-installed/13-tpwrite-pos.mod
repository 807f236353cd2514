MODULE tpwrite_pos
! @format 3
! @section 13
! @expect ok
! @description TPWrite \Pos writes the position as an aggregate [x,y,z], without spaces (installed-facts.md section 1, read as ValToStr writes it); the components here are integers.
! @output p=[100,-20,3]
! @exit 0
  PROC main()
    VAR pos p := [100, -20, 3];
    TPWrite "p=" \Pos:=p;
  ENDPROC
ENDMODULE
