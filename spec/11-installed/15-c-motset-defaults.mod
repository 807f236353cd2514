MODULE c_motset_defaults
! @format 3
! @section 11
! @expect ok
! @description C_MOTSET (ABB, motsetdata: the predefined data of the motion settings) is installed with its component types accdata, veldata, singdata and confsupdata; a program copies a part into its own data, as a RobotWare 6 cell does (VAR accdata acc_set; acc_set := C_MOTSET.acc). Its value is the documented default of each setting (doc/rulings.md R-13-motset1).
! @output 100 5000
! @output 100 100 100
! @output FALSE TRUE TRUE
! @output 100 TRUE 100
  PROC main()
    VAR accdata acc_set;
    VAR veldata vel_set;
    acc_set := C_MOTSET.acc;
    vel_set := C_MOTSET.vel;
    TPWrite NumToStr(vel_set.oride, 0) + " " + NumToStr(vel_set.max, 0);
    TPWrite NumToStr(acc_set.acc, 0) + " " + NumToStr(acc_set.ramp, 0) + " " + NumToStr(acc_set.finepramp, 0);
    TPWrite ValToStr(C_MOTSET.sing.wrist) + " " + ValToStr(C_MOTSET.conf.jsup) + " " + ValToStr(C_MOTSET.conf.lsup);
    TPWrite NumToStr(C_MOTSET.pathresol, 0) + " " + ValToStr(C_MOTSET.motionsup) + " " + NumToStr(C_MOTSET.tunevalue, 0);
  ENDPROC
ENDMODULE
