!> Code_Aster's physical quantities ("grandeurs") that parasol's fields carry: the name
!> (DEPL_R, SIEF_R, ...) and the ordered list of component names. A field holds a subset of
!> its quantity's components, always in the quantity's order (the order IMPR_RESU prints
!> them in). Component lists follow Code_Aster's catalog of physical quantities
!> (catalo/cataelem/Commons/physical_quantities.py), restricted to what parasol's element
!> families (DKT/DKQ plates, plane elements, discrete springs) and commands use: a name
!> outside this list is refused with the list of the quantity's components.
!>
!> Quantities ending in _F hold functions (a function concept per value, CREA_CHAMP
!> OPERATION='AFFE' with VALE_F) and have the components of their _R twin. VARI_R, the
!> internal variables, has components V1, V2, ... as many as a behaviour has
!> (Code_Aster's VARI_1, ... named V1 .. in TEST_RESU/NOM_CMP).
module field_quantities
    use kinds, only: i4
    use strings, only: string_t, to_upper
    use deck_catalog, only: split_words
    implicit none
    private

    !> The quantities parasol knows, by name. TYPE_CHAM is <location>_<quantity>.
    character(len=*), parameter, public :: FIELD_QUANTITY_NAMES = 'DEPL_R DEPL_F SIEF_R ' // &
        'EPSI_R TEMP_R TEMP_F NEUT_R NEUT_F GEOM_R ENER_R VARI_R HYDR_R ERRE_R SING_R ' // &
        'FER2_R FORC_R FORC_F PRES_R PRES_F'

    !> Most internal variables a VARI_R field may have (V1 .. V<n>).
    integer(i4), parameter, public :: MAX_VARI_COMPONENTS = 999

    character(len=*), parameter :: DEPL_CMPS = 'DX DY DZ DRX DRY DRZ'
    !> SIEF_R: 3D/plane stresses, discrete and beam forces, plate resultants (membrane N..,
    !> moments M.., shear Q..), nodal forces, and the equivalent stresses of SIEQ_* (stored
    !> in SIEF_R by Code_Aster).
    character(len=*), parameter :: SIEF_CMPS = 'SIXX SIYY SIZZ SIXY SIXZ SIYZ N VY VZ MT ' // &
        'MFY MFZ NXX NYY NXY MXX MYY MXY QX QY FX FY FZ MX MY MZ VMIS TRESCA PRIN_1 ' // &
        'PRIN_2 PRIN_3 VMIS_SG VECT_1_X VECT_1_Y VECT_1_Z VECT_2_X VECT_2_Y VECT_2_Z ' // &
        'VECT_3_X VECT_3_Y VECT_3_Z TRSIG TRIAX'
    !> EPSI_R: strains (EPxx), plate generalised strains (membrane E.., curvatures K..,
    !> shear GA..), equivalent strains (EQUI_*), thermal strains.
    character(len=*), parameter :: EPSI_CMPS = 'EPXX EPYY EPZZ EPXY EPXZ EPYZ EXX EYY EXY ' // &
        'KXX KYY KXY GAX GAY INVA_2 PRIN_1 PRIN_2 PRIN_3 INVA_2SG VECT_1_X VECT_1_Y ' // &
        'VECT_1_Z VECT_2_X VECT_2_Y VECT_2_Z VECT_3_X VECT_3_Y VECT_3_Z EPTHER_L EPTHER_T ' // &
        'EPTHER_N EPSECH EPHYDR'
    character(len=*), parameter :: TEMP_CMPS = 'TEMP TEMP_MIL TEMP_INF TEMP_SUP SECH'
    character(len=*), parameter :: NEUT_CMPS = 'X1 X2 X3 X4 X5 X6 X7 X8 X9 X10 X11 X12 X13 ' // &
        'X14 X15 X16 X17 X18 X19 X20 X21 X22 X23 X24 X25 X26 X27 X28 X29 X30'
    character(len=*), parameter :: GEOM_CMPS = 'X Y Z'
    character(len=*), parameter :: ENER_CMPS = 'TOTALE TRAC_COM TORSION MEMBRANE FLEXION ' // &
        'FLEX_Y FLEX_Z PLAN_XY PLAN_XZ DX DY DZ DRX DRY DRZ CISAILLE COUPL_MF'
    character(len=*), parameter :: ERRE_CMPS = 'ERREST NUEST SIGCAL TERMRE TERMR2 TERMNO ' // &
        'TERMN2 TERMSA TERMS2 TERMFL TERMF2 TERMEC TERME2'
    character(len=*), parameter :: SING_CMPS = 'DEGRE RAPPORT TAILLE'
    character(len=*), parameter :: FER2_CMPS = 'DNSXI DNSXS DNSYI DNSYS DNSXT DNSYT AYI ' // &
        'AYS AZI AZS AST ATOT DNSVOL CONSTRUC'
    character(len=*), parameter :: FORC_CMPS = 'FX FY FZ MX MY MZ'
    character(len=*), parameter :: PRES_CMPS = 'PRES CISA'

    public :: is_quantity, quantity_components, quantity_component_index, &
        quantity_is_function, quantity_real_twin, components_text

contains

    !> True when `name` is one of FIELD_QUANTITY_NAMES.
    pure logical function is_quantity(name)
        character(len=*), intent(in) :: name
        is_quantity = index(' ' // FIELD_QUANTITY_NAMES // ' ', ' ' // trim(name) // ' ') > 0 &
            .and. len_trim(name) > 0
    end function is_quantity

    !> True for the quantities whose values are functions (names ending in _F).
    pure logical function quantity_is_function(name)
        character(len=*), intent(in) :: name
        integer :: n
        n = len_trim(name)
        quantity_is_function = .false.
        if (n > 2) quantity_is_function = name(n - 1:n) == '_F'
    end function quantity_is_function

    !> The real quantity of a function quantity (NEUT_F -> NEUT_R); others unchanged.
    pure function quantity_real_twin(name) result(twin)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: twin
        twin = trim(name)
        if (quantity_is_function(twin)) twin = twin(1:len(twin) - 1) // 'R'
    end function quantity_real_twin

    !> The components of quantity `name`, in Code_Aster's order (VARI_R: V1 .. V<n_vari>,
    !> n_vari defaulting to 1). An unknown quantity has none.
    function quantity_components(name, n_vari) result(cmps)
        character(len=*), intent(in) :: name
        integer(i4), intent(in), optional :: n_vari
        type(string_t), allocatable :: cmps(:)
        integer(i4) :: k, n
        character(len=16) :: buf
        select case (quantity_real_twin(to_upper(name)))
        case ('DEPL_R')
            call split_words(DEPL_CMPS, cmps)
        case ('SIEF_R')
            call split_words(SIEF_CMPS, cmps)
        case ('EPSI_R')
            call split_words(EPSI_CMPS, cmps)
        case ('TEMP_R')
            call split_words(TEMP_CMPS, cmps)
        case ('NEUT_R')
            call split_words(NEUT_CMPS, cmps)
        case ('GEOM_R')
            call split_words(GEOM_CMPS, cmps)
        case ('ENER_R')
            call split_words(ENER_CMPS, cmps)
        case ('HYDR_R')
            call split_words('HYDR', cmps)
        case ('ERRE_R')
            call split_words(ERRE_CMPS, cmps)
        case ('SING_R')
            call split_words(SING_CMPS, cmps)
        case ('FER2_R')
            call split_words(FER2_CMPS, cmps)
        case ('FORC_R')
            call split_words(FORC_CMPS, cmps)
        case ('PRES_R')
            call split_words(PRES_CMPS, cmps)
        case ('VARI_R')
            n = 1
            if (present(n_vari)) n = max(1_i4, min(n_vari, MAX_VARI_COMPONENTS))
            allocate (cmps(n))
            do k = 1, n
                write (buf, '(a,i0)') 'V', k
                cmps(k)%s = trim(buf)
            end do
        case default
            allocate (cmps(0))
        end select
    end function quantity_components

    !> Position of component `cmp` in quantity `name` (1-based), 0 when the quantity has no
    !> such component. VARI_R accepts V1 .. V<MAX_VARI_COMPONENTS>.
    function quantity_component_index(name, cmp) result(k)
        character(len=*), intent(in) :: name, cmp
        integer(i4) :: k
        type(string_t), allocatable :: cmps(:)
        integer :: ios, n
        character(len=:), allocatable :: c
        k = 0
        c = to_upper(trim(cmp))
        if (quantity_real_twin(to_upper(name)) == 'VARI_R') then
            if (len(c) < 2 .or. len(c) > 4) return
            if (c(1:1) /= 'V' .or. verify(c(2:), '0123456789') /= 0) return
            read (c(2:), *, iostat=ios) n
            if (ios == 0 .and. n >= 1 .and. n <= MAX_VARI_COMPONENTS) k = int(n, i4)
            return
        end if
        cmps = quantity_components(name)
        do n = 1, size(cmps)
            if (cmps(n)%s == c) then
                k = int(n, i4)
                return
            end if
        end do
    end function quantity_component_index

    !> The names of `cmps` separated by blanks (for messages).
    pure function components_text(cmps) result(text)
        type(string_t), intent(in) :: cmps(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(cmps)
            if (k > 1) text = text // ' '
            text = text // cmps(k)%s
        end do
    end function components_text

end module field_quantities
