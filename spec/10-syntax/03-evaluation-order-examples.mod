MODULE evaluation_order_examples
! @section 3.1
! @expect ok
! @description The expressions of the evaluation-order table of section 3.1.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num x;
  VAR bool p;
  VAR bool q;
  VAR bool r;
  VAR bool s;
  VAR bool y;
  PROC main()
    x := a + b + c;
    x := a + b * c;
    y := p OR q OR r;
    y := p AND q OR r AND s;
    y := a < b AND c < d;
  ENDPROC
ENDMODULE
