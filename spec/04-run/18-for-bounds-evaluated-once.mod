MODULE for_bounds_evaluated_once
! @format 3
! @section 4.18
! @expect ok
! @description The FROM, TO and STEP expressions are evaluated once, before the first iteration (section 4.18): changing the variables they read inside the body does not change the loop.
! @output 1
! @output 2
! @output 3
! @output last=100 stride=50
! @exit 0
  VAR num last := 3;
  VAR num stride := 1;
  PROC main()
    FOR i FROM 1 TO last STEP stride DO
      TPWrite "" \Num:=i;
      last := 100;
      stride := 50;
    ENDFOR
    TPWrite "last=" + NumToStr(last, 0) + " stride=" + NumToStr(stride, 0);
  ENDPROC
ENDMODULE
