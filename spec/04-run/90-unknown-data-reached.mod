MODULE unknown_data_reached
! @format 3
! @section 3.6
! @section 13
! @options allow-unknown
! @expect ok
! @description With --allow-unknown a reference to a data object neither declared nor installed (an I/O signal of the controller's configuration, say) is a warning; reading it is ERR_REFUNKDAT (ch. 12).
! @exit 1
! @error ERR_REFUNKDAT 12:5
  VAR num x;
  PROC main()
    x := doUnknownSignal + 1;
  ENDPROC
ENDMODULE
