MODULE num_single_precision
! @format 3
! @section 2.13
! @section 3.12
! @expect ok
! @description num is IEEE 754 single precision and every num result is rounded to it: 16777216 + 1 is 16777216 as num; dnum is double precision and gives 16777217 (section 2.13).
! @output num unchanged=TRUE
! @output dnum one more=TRUE
! @exit 0
  PROC main()
    VAR num n := 16777216;
    VAR dnum d := 16777216;
    n := n + 1;
    d := d + 1;
    TPWrite "num unchanged=" \Bool:=n - 16777216 = 0;
    TPWrite "dnum one more=" \Bool:=d - 16777216 = 1;
  ENDPROC
ENDMODULE
