MODULE white_space_crlf
! @section 2.10
! @section 2.2
! @expect ok
! @description Lines ending with CR LF: the pair is one line break.
  VAR num x;
  PROC main()
    ! lines end with CR LF
    x := 1;
    IF x = 1 THEN
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
