MODULE rulings_norient
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-f: NOrient divides by the norm when the error |sum of q^2 - 1| is below 0.1 and is ERR_ILLQUAT otherwise; EulerZYX without \X, \Y or \Z is ERR_ARGVALERR.
! @output [1.02,0,0,0]=[1,0,0,0]
! @output [0.96,0,0,0]=[1,0,0,0]
! @output [0.7,0,0,0.7]=[0.707107,0,0,0.707107]
! @output [2,0,0,0]: ERR_ILLQUAT
! @output [0.9,0,0,0]: ERR_ILLQUAT
! @output EulerZYX without a switch: ERR_ARGVALERR
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_ILLQUAT RETURN "ERR_ILLQUAT";
    IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR orient o;
    VAR num a;
    TPWrite "[1.02,0,0,0]=" \Orient:=NOrient([1.02, 0, 0, 0]);
    TPWrite "[0.96,0,0,0]=" \Orient:=NOrient([0.96, 0, 0, 0]);
    TPWrite "[0.7,0,0,0.7]=" \Orient:=NOrient([0.7, 0, 0, 0.7]);
    what := "[2,0,0,0]";
    o := NOrient([2, 0, 0, 0]);
    what := "[0.9,0,0,0]";
    o := NOrient([0.9, 0, 0, 0]);
    what := "EulerZYX without a switch";
    a := EulerZYX([1, 0, 0, 0]);
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
