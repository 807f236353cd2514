MODULE module1
! @section 9.2
! @expect ok
! @description An empty module (the example of chapter 16, split over two lines to hold the directives).
ENDMODULE
