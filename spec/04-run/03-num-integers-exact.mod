MODULE num_integers_exact
! @format 3
! @section 2.13
! @section 3.12
! @expect ok
! @description +, - and * keep integers exact within the integer range of num (section 2.13: -8388607 to 8388608).
! @output 8388608=TRUE
! @output -8388607=TRUE
! @output product=6000
! @exit 0
  PROC main()
    VAR num a := 4194304;
    VAR num b := 200;
    VAR num c := 30;
    TPWrite "8388608=" \Bool:=a + a = 8388608;
    TPWrite "-8388607=" \Bool:=1 - a - a = -8388607;
    TPWrite "product=" \Num:=b * c;
  ENDPROC
ENDMODULE
