MODULE valtostr_use
! @format 3
! @section 13
! @expect ok
! @description ValToStr writes a value as RAPID writes it: TRUE/FALSE, an integer num without decimals, a pos as [x,y,z] without spaces (installed-facts.md section 1).
! @output TRUE
! @output -12
! @output [1,2,3]
! @exit 0
  PROC main()
    VAR bool b := TRUE;
    VAR num n := -12;
    VAR pos p := [1, 2, 3];
    TPWrite ValToStr(b);
    TPWrite ValToStr(n);
    TPWrite ValToStr(p);
  ENDPROC
ENDMODULE
