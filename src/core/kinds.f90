!> Numeric kinds used everywhere in parasol (from iso_fortran_env, in one place).
!>
!> dp  : real kind of every computed quantity (IEEE double).
!> i4  : default integer kind for counts, node and equation numbers.
!> i8  : 64-bit integers for skyline profile pointers (a profile passes 2**31 entries near a
!>       million equations, see style.md).
module kinds
    use, intrinsic :: iso_fortran_env, only: real64, int32, int64
    implicit none
    private
    integer, parameter, public :: dp = real64
    integer, parameter, public :: i4 = int32
    integer, parameter, public :: i8 = int64
end module kinds
