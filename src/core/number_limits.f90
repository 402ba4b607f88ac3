!> The ranges parasol accepts for the numbers it reads, and guards for the products it forms
!> from them, that cannot overflow themselves (issue 13; doc/stability.md, "Hostile input").
!>
!> Every number read from a deck or a mesh is finite (the readers refuse NaN, Inf and
!> numbers beyond double precision). Beyond that, the quantities whose products parasol forms
!> are bounded where they are read, generously against physics and tightly enough against
!> double precision (1.8e308) that the products formed from them later stay finite:
!>  - lengths (mesh coordinates, EPAIS, DIST_1, COOR_CENTRE): |x| <= 1e30 m, a billion times
!>    the size of the observable universe in metres; the 6th power of a length (the largest
!>    power an element forms, EPAIS**3 times an area) stays below 1e180;
!>  - a mesh spans at least 1e-30 (largest side of its bounding box), its cells are not degenerate
!>    against that span (mesh_types), so inverse lengths stay below 1e42;
!>  - moduli and stiffnesses (E, spring stiffnesses): 1e-100 <= |x| <= 1e100 or 0 (steel:
!>    2e11 Pa); EPAIS >= 1e-30; so E * EPAIS**3 stays within 1e-190 .. 1e190 and the
!>    stiffness matrix, its inverse and the solution of a bounded load stay finite.
!> Values formed at run time from deck functions (loads of FORMULE, imposed displacements)
!> are checked where they are formed with `product_fits`, which decides from the binary
!> exponents whether a product is representable, without forming it.
module number_limits
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    implicit none
    private

    !> Largest |coordinate| of a mesh node and largest length given in a deck (EPAIS,
    !> DIST_1, DIST_2, COOR_CENTRE), in the deck's length unit.
    real(dp), parameter, public :: MAX_LENGTH = 1.0e30_dp
    !> Smallest length given in a deck where it is inverted or cubed (EPAIS), and smallest
    !> span of a mesh with cells other than POI1 (largest side of its bounding box).
    real(dp), parameter, public :: MIN_LENGTH = 1.0e-30_dp
    real(dp), parameter, public :: MIN_MESH_EXTENT = MIN_LENGTH
    !> Largest modulus or stiffness (E, the values of K_T_D_N/K_T_D_L, RIGI_NOR), and the
    !> smallest one other than 0: a stiffness of 1e-320 (a denormal) has an inverse beyond
    !> double precision, and the solvers scale by 1/sqrt of the diagonal.
    real(dp), parameter, public :: MAX_MODULUS = 1.0e100_dp
    real(dp), parameter, public :: MIN_MODULUS = 1.0e-100_dp
    !> Largest |Poisson's ratio| of an orthotropic material (ELAS_ORTH NU_LT, NU_LN, NU_TN;
    !> measured ones stay below 2): with the moduli in [MIN_MODULUS, MAX_MODULUS] the
    !> compliance and its minors stay finite (below 1e310 / 1e3 ... about 1e306).
    real(dp), parameter, public :: MAX_POISSON = 1.0e3_dp
    !> Largest |temperature| a thermal strain is formed from (AFFE_VARC TEMP, VALE_REF,
    !> TEMP_DEF_ALPHA, the abscissae of ELAS_FO ALPHA), and largest |strain| formed from a
    !> deck's values (ALPHA (T - T_ref)): a stress E eps stays below 1e130.
    real(dp), parameter, public :: MAX_TEMPERATURE = 1.0e30_dp
    real(dp), parameter, public :: MAX_STRAIN = 1.0e30_dp
    !> Largest |instant| (DEFI_LIST_REEL, INST): differences of instants stay finite.
    real(dp), parameter, public :: MAX_INSTANT = 1.0e30_dp
    !> Largest magnitude of a computed quantity that products may still be formed from
    !> (2**1000, about 1.07e301): a product of two such numbers is refused by product_fits,
    !> a sum of up to 2**20 of them stays finite.
    integer, parameter, public :: MAX_BINARY_EXPONENT = 1000

    public :: is_finite, product_fits, magnitude_fits

contains

    !> True when x is neither NaN nor +-Inf.
    elemental logical function is_finite(x)
        real(dp), intent(in) :: x
        is_finite = ieee_is_finite(x)
    end function is_finite

    !> True when |a * b| < 2**MAX_BINARY_EXPONENT, decided from the binary exponents of a and
    !> b (|x| < 2**exponent(x)), so the test cannot overflow; a zero factor always fits.
    !> A non-finite factor never fits.
    elemental logical function product_fits(a, b)
        real(dp), intent(in) :: a, b
        product_fits = .false.
        if (.not. (ieee_is_finite(a) .and. ieee_is_finite(b))) return
        if (.not. (abs(a) > 0.0_dp .and. abs(b) > 0.0_dp)) then
            product_fits = .true.
            return
        end if
        product_fits = exponent(a) + exponent(b) <= MAX_BINARY_EXPONENT
    end function product_fits

    !> True when x is finite and |x| < 2**MAX_BINARY_EXPONENT.
    elemental logical function magnitude_fits(x)
        real(dp), intent(in) :: x
        magnitude_fits = .false.
        if (.not. ieee_is_finite(x)) return
        magnitude_fits = exponent(x) <= MAX_BINARY_EXPONENT   ! exponent(0) = 0
    end function magnitude_fits

end module number_limits
