!> Spring results as Code_Aster's element fields, read by TEST_RESU and IMPR_RESU:
!>  SIEF_ELGA : the discrete's forces in its element frame, components N, VY, VZ (DIS_T) or
!>              N, VY (2D_DIS_T) (Code_Aster's element catalogue MECA_DIS_T_L and
!>              MECA_2D_DIS_T_L, located components EEFGEGA);
!>  VARI_ELGA : the internal variables of the contact law, components V1, V2, ...
!> A SEG2 discrete has its Gauss points at its two nodes (catalogue: RIGI=NOEU): POINT 1 and
!> POINT 2. Code_Aster's DIS_CHOC stores the same values at both (dis_choc_frot.F90), and so
!> does parasol.
!>
!> DIS_CHOC internal variables (Code_Aster 17, behaviour catalogue dis_choc.py: 10
!> variables; meanings from dis_choc_frot_syme.F90), for a spring without friction
!> (COULOMB = 0, the only case parasol runs):
!>   V1  normal gap d = L + (u2 - u1).x - DIST_1 - DIST_2, <= 0 in contact (Code_Aster
!>       subtracts one more machine epsilon, 2.2e-16 m: parasol stores the gap its own law
!>       decides the status with, element_dis_choc)
!>   V2, V3  relative displacement across the spring, (u2 - u1).y and (u2 - u1).z (V3 = 0
!>       in 2D)
!>   V4  state: 0 in contact (adherent), 2 open (decolle); 1 (sliding) needs friction
!>   V5, V6  tangential displacement where sliding began: 0 without friction
!>   V7  normal force N (<= 0, compression), as SIEF_ELGA N
!>   V8, V9  friction forces: 0 without friction
!>   V10 integration scheme: 1 (the velocity form Code_Aster uses in statics)
!> Code_Aster keeps V4 at 2 once a spring has opened, even when it closes again in a later
!> step (its local-frame branch never writes the contact state); parasol writes the state
!> of the step, 0 again for a spring that closed.
module element_spring_fields
    use kinds, only: dp, i4
    use strings, only: to_upper
    implicit none
    private

    !> Gauss points of a SEG2 discrete (one at each node).
    integer(i4), parameter, public :: SPRING_POINTS = 2
    !> SIEF_ELGA components of DIS_T (the first two for 2D_DIS_T).
    character(len=2), parameter, public :: SIEF_COMPONENTS(3) = ['N ', 'VY', 'VZ']
    !> DIS_CHOC internal variables (module header).
    integer(i4), parameter, public :: DIS_CHOC_N_VARI = 10
    !> V4 of DIS_CHOC: in contact, open.
    real(dp), parameter, public :: DIS_CHOC_CLOSED = 0.0_dp, DIS_CHOC_OPEN = 2.0_dp
    !> V10 of DIS_CHOC: Code_Aster's "EnVitesse" scheme.
    real(dp), parameter :: DIS_CHOC_SCHEME = 1.0_dp

    public :: dis_choc_fields, sief_component_index, vari_component_index, vari_name

contains

    !> SIEF_ELGA and VARI_ELGA of a DIS_CHOC SEG2 (both points) from its state.
    !>  ndim   : in, 3 (DIS_T) or 2 (2D_DIS_T)
    !>  closed : in, in contact;  gap : in, the law's normal gap d (V1)
    !>  force  : in, the force on node 2 in the element frame (x along node 1 -> node 2):
    !>           (N, VY, VZ); N <= 0 in contact
    !>  rel    : in, u2 - u1 in the element frame
    !>  sief   : out, (N, VY, VZ), all 0 when |N| is below the machine epsilon (as
    !>           Code_Aster: a contact force that small is no contact);  0 past ndim
    !>  vari   : out, V1 .. V10 (module header)
    pure subroutine dis_choc_fields(ndim, closed, gap, force, rel, sief, vari)
        integer(i4), intent(in) :: ndim
        logical, intent(in) :: closed
        real(dp), intent(in) :: gap, force(3), rel(3)
        real(dp), intent(out) :: sief(3), vari(DIS_CHOC_N_VARI)
        sief = 0.0_dp
        sief(1:ndim) = force(1:ndim)
        if (.not. closed .or. abs(sief(1)) < epsilon(1.0_dp)) sief = 0.0_dp
        vari = 0.0_dp
        vari(1) = gap
        vari(2:ndim) = rel(2:ndim)
        vari(4) = merge(DIS_CHOC_CLOSED, DIS_CHOC_OPEN, closed)
        if (closed) vari(7) = min(force(1), 0.0_dp)
        vari(10) = DIS_CHOC_SCHEME
    end subroutine dis_choc_fields

    !> Index of a SIEF_ELGA component (N, VY, VZ; VZ only in 3D), 0 if none.
    pure integer(i4) function sief_component_index(name, ndim) result(k)
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: ndim
        do k = 1, ndim
            if (to_upper(trim(name)) == trim(SIEF_COMPONENTS(k))) return
        end do
        k = 0
    end function sief_component_index

    !> Index of a VARI_ELGA component V1 .. Vn_vari, 0 if none.
    pure integer(i4) function vari_component_index(name, n_vari) result(k)
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: n_vari
        integer :: ios
        character(len=:), allocatable :: upper
        upper = to_upper(trim(name))
        k = 0
        if (len(upper) < 2 .or. len(upper) > 4) return
        if (upper(1:1) /= 'V' .or. verify(upper(2:), '0123456789') /= 0) return
        read (upper(2:), *, iostat=ios) k
        if (ios /= 0 .or. k < 1 .or. k > n_vari) k = 0
    end function vari_component_index

    !> Name of VARI_ELGA component k: 'V' // k.
    pure function vari_name(k) result(name)
        integer(i4), intent(in) :: k
        character(len=:), allocatable :: name
        character(len=12) :: buf
        write (buf, '(i0)') k
        name = 'V' // trim(buf)
    end function vari_name

end module element_spring_fields
