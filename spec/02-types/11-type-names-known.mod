MODULE type_names_known
! @format 2
! @section 2.11
! @section 2.13
! @section 2.14
! @section 2.15
! @expect ok
! @description Every type name available without a declaration: num, dnum, bool, string, pos, orient, pose, errnum, intnum, and the installed signaldi and iodev.
  VAR num n;
  VAR dnum d;
  VAR bool b;
  VAR string s;
  VAR pos p;
  VAR orient o;
  VAR pose pp;
  VAR errnum e;
  VAR intnum i;
  VAR signaldi di1;
  VAR iodev dev;
ENDMODULE
