MODULE optional_named_no_backslash
! @format 2
! @section 4.6
! @section 5.2
! @expect semantic-error 12:15
! @description wobj:=2 names the optional parameter \wobj without its backslash: it is read as a required argument, one more than move takes (the hint: \wobj:=2).
  PROC move(num speed \num wobj)
    TPWrite "moved", \Num:=speed;
  ENDPROC

  PROC main()
    move 100, wobj:=2;
  ENDPROC
ENDMODULE
