MODULE placeholder_argument
! @format 3
! @section 1.2
! @section 4.6
! @expect ok
! @description A call whose argument is the placeholder <ARG> raises ERR_EXECPHR at the call, before the procedure runs (section 1.2).
! @exit 1
! @error ERR_EXECPHR 13:5
  PROC show(num n)
    TPWrite "show" \Num:=n;
  ENDPROC
  PROC main()
    show <ARG>;
  ENDPROC
ENDMODULE
