MODULE late_local_main
! @format 3
! @section 4.6
! @section 5.3
! @expect ok
! @description "lib:secret" calls the LOCAL procedure secret of module lib from another module (section 4.6: name2 may be declared locally in name1); a plain late-bound name finds a global procedure of any task module.
! @output secret of lib
! @output global of lib
! @exit 0
  PROC main()
    % "lib:secret" %;
    % "shared" %;
  ENDPROC
ENDMODULE
