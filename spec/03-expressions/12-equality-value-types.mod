MODULE equality_value_types
! @format 2
! @section 3.12
! @expect ok
! @description Rows = and <>: any value type, both operands of equal type -> bool.
  RECORD pair
    num a;
    string b;
  ENDRECORD
  VAR num n;
  VAR dnum d;
  VAR bool b;
  VAR string s;
  VAR pos p;
  VAR orient o;
  VAR pose pp;
  VAR pair pr;
  VAR errnum e;
  VAR bool r;
  PROC main()
    r := n = n;
    r := d <> d;
    r := b = b;
    r := s <> s;
    r := p = p;
    r := o <> o;
    r := pp = pp;
    r := pr = pr;
    r := e = n;
  ENDPROC
ENDMODULE
