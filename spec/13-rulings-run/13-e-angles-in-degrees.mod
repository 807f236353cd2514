MODULE rulings_angles
! @format 3
! @section 13
! @expect ok
! @description R-13-e: Sin, Cos and Tan take degrees and reduce the angle exactly to a quadrant, so Sin(180), Sin(720) and Cos(90) are exactly 0 and Sin(90) exactly 1; ASin, ACos, ATan and ATan2 return degrees (-90..90, 0..180, -90..90, -180..180), and ATan2(0,0) is 0.
! @output Sin(180) = 0 TRUE
! @output Sin(720) = 0 TRUE
! @output Sin(-180) = 0 TRUE
! @output Cos(90) = 0 TRUE
! @output Cos(-270) = 0 TRUE
! @output Sin(90) = 1 TRUE
! @output Sin(-90) = -1 TRUE
! @output Cos(180) = -1 TRUE
! @output Cos(360) = 1 TRUE
! @output Sin(180)=0
! @output ASin(1)=90
! @output ASin(-1)=-90
! @output ASin(0.5)=30
! @output ACos(-1)=180
! @output ACos(1)=0
! @output ATan(1)=45
! @output ATan(-1)=-45
! @output ATan2(1,-1)=135
! @output ATan2(-1,-1)=-135
! @output ATan2(0,0)=0
! @exit 0
  PROC main()
    TPWrite "Sin(180) = 0 " \Bool:=Sin(180) = 0;
    TPWrite "Sin(720) = 0 " \Bool:=Sin(720) = 0;
    TPWrite "Sin(-180) = 0 " \Bool:=Sin(-180) = 0;
    TPWrite "Cos(90) = 0 " \Bool:=Cos(90) = 0;
    TPWrite "Cos(-270) = 0 " \Bool:=Cos(-270) = 0;
    TPWrite "Sin(90) = 1 " \Bool:=Sin(90) = 1;
    TPWrite "Sin(-90) = -1 " \Bool:=Sin(-90) = -1;
    TPWrite "Cos(180) = -1 " \Bool:=Cos(180) = -1;
    TPWrite "Cos(360) = 1 " \Bool:=Cos(360) = 1;
    TPWrite "Sin(180)=" \Num:=Sin(180);
    TPWrite "ASin(1)=" \Num:=ASin(1);
    TPWrite "ASin(-1)=" \Num:=ASin(-1);
    TPWrite "ASin(0.5)=" \Num:=ASin(0.5);
    TPWrite "ACos(-1)=" \Num:=ACos(-1);
    TPWrite "ACos(1)=" \Num:=ACos(1);
    TPWrite "ATan(1)=" \Num:=ATan(1);
    TPWrite "ATan(-1)=" \Num:=ATan(-1);
    TPWrite "ATan2(1,-1)=" \Num:=ATan2(1, -1);
    TPWrite "ATan2(-1,-1)=" \Num:=ATan2(-1, -1);
    TPWrite "ATan2(0,0)=" \Num:=ATan2(0, 0);
  ENDPROC
ENDMODULE
