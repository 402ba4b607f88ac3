!> The catalog of AFFE_CARA_ELEM (U4.42.01).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_cara_elem
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, &
        RULE_PRESENT_PRESENT, RULE_ENSEMBLE
    use number_limits, only: MAX_LENGTH, MIN_LENGTH, MAX_MODULUS, MIN_MODULUS
    use catalog_common, only: OUI_NON, ANGLE_MAX, RATIO_MAX, WEIGHT_MAX
    implicit none
    private
    public :: describe_cara_elem

contains

    subroutine describe_cara_elem(c)
        type(catalog_t), intent(inout) :: c
        character(len=*), parameter :: K_CARA = 'K_T_D_N K_T_D_L K_TR_D_N K_TR_D_L'
        call c%command('AFFE_CARA_ELEM', 'cara_elem')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VERIF', 'TXM', max=MANY, into='MAILLE')
        call c%fact('COQUE', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('EPAIS', 'R', req=.true., vmax=MAX_LENGTH, vtiny=MIN_LENGTH)  ! > 0: handler
        call c%key('COQUE_NCOU', 'I', def='1', vmin=1.0_dp, vmax=1000.0_dp)   ! layers
        call c%key('COEF_RIGI_DRZ', 'R', def='1.0E-5', &  ! Code_Aster default
                   vmin=-RATIO_MAX, vmax=RATIO_MAX)
        call c%key('ANGL_REP', 'R', min=2, max=2, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('VECTEUR', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('EXCENTREMENT', 'R', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('INER_ROTA', 'TXM', into=OUI_NON, noop=.true.)   ! masses only
        call c%key('MODI_METRIQUE', 'TXM', into=OUI_NON, noop=.true.)
        call c%rule(RULE_EXCLUS, 'ANGL_REP VECTEUR')
        call c%rule(RULE_PRESENT_PRESENT, 'EXCENTREMENT INER_ROTA')
        call c%end_fact()
        call c%fact('DISCRET', max=MANY)
        call describe_discrete(c, .false.)
        call c%end_fact()
        call c%fact('DISCRET_2D', max=MANY)
        call describe_discrete(c, .true.)
        call c%end_fact()
        ! MASSIF: the material frame of plane (and volume) elements, as data (Code_Aster
        ! affe_cara_elem.py); only an orthotropic material turns with it.
        call c%fact('MASSIF', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('CHAM_ORIE', 'cham_no_sdaster|carte_sdaster')
        call c%key('ANGL_REP', 'R', min=1, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ANGL_EULER', 'R', min=1, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ANGL_AXE', 'R', min=2, max=2, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ORIG_AXE', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%rule(RULE_UN_PARMI, 'GROUP_MA TOUT')
        call c%rule(RULE_UN_PARMI, 'ANGL_REP ORIG_AXE ANGL_EULER CHAM_ORIE')
        call c%rule(RULE_PRESENT_PRESENT, 'ANGL_AXE ORIG_AXE')
        call c%rule(RULE_ENSEMBLE, 'TOUT CHAM_ORIE')
        call c%end_fact()
        call c%fact('ORIENTATION', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('CARA', 'TXM', req=.true., into='ANGL_VRIL VECT_Y ANGL_NAUT')
        call c%key('VALE', 'R', max=3, req=.true., vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%end_fact()
        call c%fact('RIGI_PARASOL', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('GROUP_MA_SEG2', 'TXM', max=MANY)
        call c%key('GROUP_MA_POI1', 'TXM', max=MANY)
        call c%key('COEF_GROUP', 'R', max=MANY, vmin=-WEIGHT_MAX, vmax=WEIGHT_MAX, &
                   vtiny=1.0_dp / WEIGHT_MAX)
        call c%key('FONC_GROUP', 'FUNC', max=MANY)
        call c%key('CARA', 'TXM', max=2, req=.true., into=K_CARA)
        call c%key('VALE', 'R', max=MANY, req=.true., vmin=-MAX_MODULUS, vmax=MAX_MODULUS, &
                   vtiny=MIN_MODULUS)
        call c%key('REPERE', 'TXM', def='GLOBAL', into='GLOBAL')
        call c%key('GROUP_NO_CENTRE', 'TXM')
        call c%key('NOEUD_CENTRE', 'TXM')
        call c%key('COOR_CENTRE', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%rule(RULE_UN_PARMI, 'GROUP_MA_SEG2 GROUP_MA_POI1')
        call c%rule(RULE_UN_PARMI, 'COEF_GROUP FONC_GROUP')
        call c%rule(RULE_EXCLUS, 'GROUP_NO_CENTRE NOEUD_CENTRE COOR_CENTRE')
        call c%end_fact()
        call c%rule(RULE_AU_MOINS_UN, 'COQUE DISCRET DISCRET_2D ORIENTATION MASSIF RIGI_PARASOL')
        call c%rule(RULE_EXCLUS, 'DISCRET DISCRET_2D')
    end subroutine describe_cara_elem

    ! DISCRET / DISCRET_2D as Code_Aster's catalog (affe_cara_elem.py): SYME 'OUI' takes
    ! the 24 characteristics K_, M_, A_ (stiffness, mass, damping), SYME 'NON' the 12 full
    ! ones; each CARA its GROUP_MA and its number of VALE (3D | 2D): a diagonal one its
    ! DOFs per node; a full one the upper triangle by column (SYME 'OUI') or the whole
    ! matrix by column ('NON'); M_T_D_* the mass, M_TR_D_N the mass, inertia tensor and
    ! offset, M_TR_D_L the mass and inertia.
    subroutine describe_discrete(c, two_d)
        type(catalog_t), intent(inout) :: c
        logical, intent(in) :: two_d
        character(len=*), parameter :: SYMMETRIC = 'K_T_D_N K_T_D_L K_TR_D_N K_TR_D_L ' // &
            'K_T_N K_T_L K_TR_N K_TR_L M_T_D_N M_T_D_L M_TR_D_N M_TR_D_L M_T_N M_T_L ' // &
            'M_TR_N M_TR_L A_T_D_N A_T_D_L A_TR_D_N A_TR_D_L A_T_N A_T_L A_TR_N A_TR_L'
        character(len=*), parameter :: FULL = 'K_T_N K_T_L K_TR_N K_TR_L M_T_N M_T_L ' // &
            'M_TR_N M_TR_L A_T_N A_T_L A_TR_N A_TR_L'
        call c%key('REPERE', 'TXM', def='GLOBAL', into='LOCAL GLOBAL')
        call c%key('AMOR_HYST', 'R', noop=.true.)
        call c%key('SYME', 'TXM', def='OUI', into=OUI_NON)
        call c%bloc(key='SYME', equals='OUI')
        call c%key('CARA', 'TXM', into=SYMMETRIC)
        call values_bloc('K_T_D_N A_T_D_N', 3, 2)
        call values_bloc('K_T_D_L A_T_D_L', 3, 2)
        call values_bloc('K_TR_D_N A_TR_D_N', 6, 3)
        call values_bloc('K_TR_D_L A_TR_D_L', 6, 3)
        call values_bloc('K_T_N A_T_N M_T_N', 6, 3)
        call values_bloc('K_T_L A_T_L M_T_L', 21, 10)
        call values_bloc('K_TR_N A_TR_N M_TR_N', 21, 6)
        call values_bloc('K_TR_L A_TR_L M_TR_L', 78, 21)
        call values_bloc('M_T_D_N', 1, 1)
        call values_bloc('M_T_D_L', 1, 1)
        call values_bloc('M_TR_D_N', 10, 4)
        call values_bloc('M_TR_D_L', 4, 2)
        call c%end_bloc()
        call c%bloc(key='SYME', equals='NON')
        call c%key('CARA', 'TXM', into=FULL)
        call values_bloc('K_T_N A_T_N M_T_N', 9, 4)
        call values_bloc('K_T_L A_T_L M_T_L', 36, 16)
        call values_bloc('K_TR_N A_TR_N M_TR_N', 36, 9)
        call values_bloc('K_TR_L A_TR_L M_TR_L', 144, 36)
        call c%end_bloc()
    contains
        subroutine values_bloc(caras, n3, n2)
            character(len=*), intent(in) :: caras
            integer, intent(in) :: n3, n2
            integer :: n
            n = merge(n2, n3, two_d)
            call c%bloc(key='CARA', equals=caras)
            call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
            call c%key('VALE', 'R', min=n, max=n, req=.true., vmin=-MAX_MODULUS, &
                       vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
            call c%end_bloc()
        end subroutine values_bloc
    end subroutine describe_discrete

end module catalog_cara_elem
