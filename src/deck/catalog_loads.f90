!> The catalog of the load commands: AFFE_CHAR_MECA(_F), AFFE_CHAR_CINE(_F).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_loads
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, &
        RULE_PRESENT_ABSENT
    use number_limits, only: MAX_LENGTH, MAX_MODULUS, MIN_MODULUS
    use catalog_common, only: OUI_NON, ANGLE_MAX
    implicit none
    private
    public :: describe_loads

contains

    subroutine describe_loads(c)
        type(catalog_t), intent(inout) :: c
        call describe_load_command(c, 'AFFE_CHAR_MECA', 'R')
        call describe_load_command(c, 'AFFE_CHAR_MECA_F', 'FUNC')
        call describe_kinematic_load(c, 'AFFE_CHAR_CINE', 'R')
        call describe_kinematic_load(c, 'AFFE_CHAR_CINE_F', 'FUNC')
    end subroutine describe_loads

    !> AFFE_CHAR_CINE / AFFE_CHAR_CINE_F (Code_Aster U4.44.03): imposed values eliminated
    !> from the system (no Lagrange multipliers), MECA_IMPO; NOEUD and EVOL_IMPO (with
    !> NOM_CMP) in the real form only.
    subroutine describe_kinematic_load(c, name, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, vtype
        call c%command(name, 'char_cine_meca')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        if (vtype == 'R') then          ! EVOL_IMPO: the displacement of a result in time
            call c%rule(RULE_UN_PARMI, 'MECA_IMPO EVOL_IMPO')
            call c%key('EVOL_IMPO', 'evol_elas|evol_noli')
            call c%key('NOM_CMP', 'TXM', max=MANY, into='DX DY DZ DRX DRY DRZ')
            call c%fact('MECA_IMPO', max=MANY)
        else
            call c%fact('MECA_IMPO', max=MANY, req=.true.)
        end if
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        if (vtype == 'R') then
            call c%key('NOEUD', 'TXM', max=MANY)
            call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA GROUP_NO NOEUD')
        else
            call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA GROUP_NO')
        end if
        call add_components(c, 'DX DY DZ DRX DRY DRZ', vtype)
        call c%end_fact()
    end subroutine describe_kinematic_load

    !> AFFE_CHAR_MECA (values are reals) and AFFE_CHAR_MECA_F (values are functions).
    subroutine describe_load_command(c, name, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, vtype
        character(len=*), parameter :: DOFS = 'DX DY DZ DRX DRY DRZ'
        call c%command(name, 'char_meca')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VERI_NORM', 'TXM', into=OUI_NON, noop=.true.)
        ! parasol eliminates the relations: no Lagrange multipliers to double (analysis.md)
        call c%key('DOUBLE_LAGRANGE', 'TXM', def='OUI', into=OUI_NON, noop=.true.)
        if (vtype == 'R') then
            call c%key('VERI_AFFE', 'TXM', def='OUI', into=OUI_NON, noop=.true.)
            call c%key('CARA_ELEM', 'cara_elem')
            call c%key('CHAM_MATER', 'cham_mater')
        end if
        call c%fact('DDL_IMPO', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%key('SANS_GROUP_MA', 'TXM', max=MANY)
        call c%key('SANS_GROUP_NO', 'TXM', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT GROUP_NO GROUP_MA NOEUD')
        call c%key('BLOCAGE', 'TXM', max=2, into='DEPLACEMENT ROTATION')
        call add_components(c, DOFS, vtype, also='BLOCAGE', bound=MAX_LENGTH)  ! lengths, angles
        call c%end_fact()
        if (vtype == 'R') then          ! values of a field (field's PROJ_CHAMP zooms)
            call c%fact('CHAMNO_IMPO', max=MANY)
            call c%key('CHAM_NO', 'cham_no_sdaster', req=.true.)
            call c%key('COEF_IMPO', 'R', req=.true.)
            call c%key('NUME_LAGR', 'TXM', def='NORMAL', into='NORMAL APRES', noop=.true.)
            call c%end_fact()
        end if
        call describe_face_impo(c, 'FACE_IMPO', DOFS // ' DNOR DRNOR DTAN', vtype)
        if (vtype == 'R') call describe_face_impo(c, 'ARETE_IMPO', 'DX DY DZ DTAN', vtype)
        call describe_relations(c, vtype)
        call c%fact('FORCE_NODALE', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'GROUP_NO NOEUD')
        call add_components(c, 'FX FY FZ MX MY MZ', vtype)
        if (vtype == 'R') then
            call c%key('ANGL_NAUT', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        else
            call c%key('ANGL_NAUT', vtype, max=3)
        end if
        call c%end_fact()
        call describe_force_coque(c, vtype)
        call c%fact('PRES_REP', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call add_components(c, 'PRES CISA_2D', vtype)
        call c%end_fact()
        call c%fact('FORCE_CONTOUR', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call add_components(c, 'FX FY FZ', vtype)
        call c%end_fact()
        ! initial strains of the plane (EPXX .. EPXY) and plate (EXX .. KXY) elements; the
        ! 3D, beam and field forms (EPXZ, EPYZ, EPX, KY, KZ, VECT_N, EPSI) have no element
        call c%fact('PRE_EPSI', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call add_components(c, 'EPXX EPYY EPZZ EPXY EXX EYY EXY KXX KYY KXY', vtype)
        call c%end_fact()
        call c%fact('FORCE_ARETE', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call add_components(c, 'FX FY FZ MX MY MZ', vtype)
        call c%end_fact()
        call c%fact('FORCE_INTERNE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call add_components(c, 'FX FY FZ', vtype)
        call c%end_fact()
        if (vtype /= 'R') return
        ! gravity: Code_Aster has it in AFFE_CHAR_MECA only (capesa)
        call c%fact('PESANTEUR', max=1)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GRAVITE', 'R', req=.true., vmin=-MAX_MODULUS, vmax=MAX_MODULUS)
        call c%key('DIRECTION', 'R', min=3, max=3, req=.true., vmin=-MAX_MODULUS, &
                   vmax=MAX_MODULUS)
        call c%end_fact()
        ! FORCE_COQUE_FO: a pressure on plates given by a function of space, not of time
        ! (Code_Aster has it in AFFE_CHAR_MECA only), evaluated once per cell at its centre
        ! with X, Y, Z, EP, RHO (model/force_coque_fo)
        call c%fact('FORCE_COQUE_FO', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%key('PRES', 'FUNC')
        call c%end_fact()
        call c%rule(RULE_EXCLUS, 'FORCE_COQUE FORCE_COQUE_FO')
    end subroutine describe_load_command

    !> FORCE_COQUE (Code_Aster U4.44.01): PRES, or FX..MZ in the global frame, or F1, F2,
    !> F3, MF1, MF2 in the plate's user frame (COQUE/ANGL_REP), on the plane PLAN.
    subroutine describe_force_coque(c, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: vtype
        character(len=*), parameter :: GLOBAL = 'FX FY FZ MX MY MZ', LOCAL = 'F1 F2 F3 MF1 MF2'
        integer :: i, j
        call c%fact('FORCE_COQUE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call add_components(c, 'PRES ' // GLOBAL // ' ' // LOCAL, vtype)
        i = 1
        do while (i <= len(GLOBAL))
            j = index(GLOBAL(i:) // ' ', ' ') + i - 1
            call c%rule(RULE_PRESENT_ABSENT, GLOBAL(i:j - 1) // ' PRES ' // LOCAL)
            i = j + 1
        end do
        i = 1
        do while (i <= len(LOCAL))
            j = index(LOCAL(i:) // ' ', ' ') + i - 1
            call c%rule(RULE_PRESENT_ABSENT, LOCAL(i:j - 1) // ' PRES ' // GLOBAL)
            i = j + 1
        end do
        call c%rule(RULE_PRESENT_ABSENT, 'PRES ' // GLOBAL // ' ' // LOCAL)
        call c%key('PLAN', 'TXM', def='MAIL', into='SUP INF MOY MAIL')
        call c%end_fact()
    end subroutine describe_force_coque

    !> FACE_IMPO / ARETE_IMPO: components imposed on the nodes of a face or an edge, and
    !> the normal (DNOR, DRNOR) or tangent (DTAN) component as relations (Code_Aster's
    !> rules: DNOR and DTAN exclude the DX .. DRZ).
    subroutine describe_face_impo(c, name, components, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, components, vtype
        character(len=*), parameter :: DOFS(6) = ['DX ', 'DY ', 'DZ ', 'DRX', 'DRY', 'DRZ']
        integer :: k
        call c%fact(name, max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('SANS_GROUP_MA', 'TXM', max=MANY)
        call c%key('SANS_GROUP_NO', 'TXM', max=MANY)
        call add_components(c, components, vtype, bound=MAX_LENGTH)
        do k = 1, 6
            if (index(' ' // components // ' ', ' ' // trim(DOFS(k)) // ' ') == 0) cycle
            if (index(components, 'DNOR') > 0) call c%rule(RULE_EXCLUS, 'DNOR ' // DOFS(k))
            call c%rule(RULE_EXCLUS, 'DTAN ' // DOFS(k))
        end do
        call c%end_fact()
    end subroutine describe_face_impo

    !> The LIAISON_* keywords (linear relations between components; Code_Aster U4.44.01):
    !> LIAISON_DDL, LIAISON_OBLIQUE, LIAISON_GROUP, LIAISON_UNIF, and in AFFE_CHAR_MECA
    !> LIAISON_SOLIDE, LIAISON_MAIL, LIAISON_PROJ and LIAISON_RBE3.
    subroutine describe_relations(c, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: vtype
        character(len=*), parameter :: DOFS = 'DX DY DZ DRX DRY DRZ'
        call c%fact('LIAISON_DDL', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'GROUP_NO NOEUD')
        call c%key('DDL', 'TXM', max=MANY, req=.true., into=DOFS)
        if (vtype == 'R') then
            call c%key('COEF_MULT', 'R', max=MANY, req=.true., vmin=-MAX_MODULUS, &
                       vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        else
            call c%key('COEF_MULT', 'R', max=MANY, vmin=-MAX_MODULUS, vmax=MAX_MODULUS, &
                       vtiny=MIN_MODULUS)
            call c%key('COEF_MULT_FONC', 'FUNC|nappe', max=MANY)
            call c%rule(RULE_UN_PARMI, 'COEF_MULT COEF_MULT_FONC')
        end if
        call add_value(c, 'COEF_IMPO', vtype, req=.true.)
        call c%end_fact()

        call c%fact('LIAISON_OBLIQUE', max=MANY)
        call add_node_keywords(c)
        call c%rule(RULE_AU_MOINS_UN, 'GROUP_MA GROUP_NO')
        call c%key('ANGL_NAUT', 'R', max=3, req=.true., vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call add_components(c, DOFS, vtype, bound=MAX_LENGTH)
        call c%end_fact()

        call c%fact('LIAISON_GROUP', max=MANY)
        call c%key('GROUP_MA_1', 'TXM', max=MANY)
        call c%key('GROUP_NO_1', 'TXM', max=MANY)
        call c%key('GROUP_MA_2', 'TXM', max=MANY)
        call c%key('GROUP_NO_2', 'TXM', max=MANY)
        call c%key('SANS_GROUP_NO', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'GROUP_MA_1 GROUP_NO_1')
        call c%rule(RULE_UN_PARMI, 'GROUP_MA_2 GROUP_NO_2')
        call c%rule(RULE_EXCLUS, 'GROUP_MA_1 GROUP_NO_2')
        call c%rule(RULE_EXCLUS, 'GROUP_NO_1 GROUP_MA_2')
        call c%key('DDL_1', 'TXM', max=MANY, req=.true., into=DOFS // ' DNOR')
        call c%key('COEF_MULT_1', 'R', max=MANY, req=.true., vmin=-MAX_MODULUS, &
                   vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('DDL_2', 'TXM', max=MANY, req=.true., into=DOFS // ' DNOR')
        call c%key('COEF_MULT_2', 'R', max=MANY, req=.true., vmin=-MAX_MODULUS, &
                   vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call add_value(c, 'COEF_IMPO', vtype, req=.true.)
        call c%key('TRAN', 'R', max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('ANGL_NAUT', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('CENTRE', 'R', max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%end_fact()

        call c%fact('LIAISON_UNIF', max=MANY)
        call add_node_keywords(c)
        call c%rule(RULE_UN_PARMI, 'GROUP_NO GROUP_MA')
        call c%key('DDL', 'TXM', max=MANY, req=.true., into=DOFS)
        call c%end_fact()
        if (vtype /= 'R') return

        call c%fact('LIAISON_SOLIDE', max=MANY)
        call add_node_keywords(c)
        call c%rule(RULE_UN_PARMI, 'GROUP_NO GROUP_MA')
        call c%key('DIST_MIN', 'R', vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%end_fact()

        ! LIAISON_MAIL (Code_Aster affe_char_meca.py): slave nodes tied to the master cells'
        ! shape functions (relation_mail).
        call c%fact('LIAISON_MAIL', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'GROUP_MA_ESCL GROUP_NO_ESCL')
        call c%key('GROUP_MA_MAIT', 'TXM', max=MANY)
        call c%key('GROUP_MA_ESCL', 'TXM', max=MANY)
        call c%key('GROUP_NO_ESCL', 'TXM', max=MANY)
        call c%key('DISTANCE_MAX', 'R', vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%key('DISTANCE_ALARME', 'R', vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%key('TYPE_RACCORD', 'TXM', def='MASSIF', &
                   into='MASSIF COQUE COQUE_MASSIF MASSIF_COQUE')
        call c%bloc(key='TYPE_RACCORD', equals='COQUE')
        call c%key('TRANSF_GEOM_MAIT', 'FUNC', min=3, max=3)
        call c%key('TRANSF_GEOM_ESCL', 'FUNC', min=3, max=3)
        call c%key('DDL', 'TXM', max=6, into=DOFS)
        call c%end_bloc()
        call c%bloc(key='TYPE_RACCORD', equals='MASSIF')
        call c%key('TRAN', 'R', max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('ANGL_NAUT', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('CENTRE', 'R', max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('DDL', 'TXM', max=MANY, into=DOFS // ' DNOR')
        call c%end_bloc()
        call c%bloc(key='TYPE_RACCORD', equals='COQUE_MASSIF')
        call c%key('EPAIS', 'R', req=.true., vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%key('CHAM_NORMALE', 'cham_no_sdaster', req=.true.)
        call c%end_bloc()
        call c%key('ELIM_MULT', 'TXM', def='OUI', into=OUI_NON)
        call c%end_fact()

        ! LIAISON_PROJ (Code_Aster affe_char_meca.py): the relations of a PROJ_CHAMP
        ! correspondence (relation_proj). DDL: Code_Aster takes any mechanical component
        ! (C_NOM_DDL_INTO('MECANIQUE')); parasol's elements have these. TYPE defaults to
        ! 'IDENTITE' as in Code_Aster.
        call c%fact('LIAISON_PROJ', max=MANY)
        call c%key('MATR_PROJECTION', 'corresp_2_mailla', req=.true.)
        call c%key('DDL', 'TXM', max=MANY, req=.true., into=DOFS)
        call c%key('TYPE', 'TXM', def='IDENTITE', into='IDENTITE EXCENTREMENT')
        call c%end_fact()

        call c%fact('LIAISON_RBE3', max=MANY)
        call c%key('GROUP_NO_MAIT', 'TXM')
        call c%key('DDL_MAIT', 'TXM', max=6, req=.true., into=DOFS)
        call c%key('GROUP_NO_ESCL', 'TXM', max=MANY)
        call c%key('DDL_ESCL', 'TXM', max=MANY, req=.true.)
        call c%key('COEF_ESCL', 'R', max=MANY, def='1.0', vmin=-MAX_MODULUS, &
                   vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%end_fact()
    end subroutine describe_relations

    ! GROUP_NO, GROUP_MA, SANS_GROUP_MA, SANS_GROUP_NO of a relation keyword.
    subroutine add_node_keywords(c)
        type(catalog_t), intent(inout) :: c
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('SANS_GROUP_MA', 'TXM', max=MANY)
        call c%key('SANS_GROUP_NO', 'TXM', max=MANY)
    end subroutine add_node_keywords

    ! A value keyword: a real within +-MAX_LENGTH (AFFE_CHAR_MECA) or a function.
    subroutine add_value(c, name, vtype, req)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, vtype
        logical, intent(in) :: req
        if (vtype == 'R') then
            call c%key(name, vtype, req=req, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        else
            call c%key(name, vtype, req=req)
        end if
    end subroutine add_value

    !> Optional components (at least one of them, or of the keywords `also`) of a load
    !> factor keyword; real values within +-bound when given (functions are checked where
    !> they are evaluated, model_loads).
    subroutine add_components(c, names, vtype, also, bound)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: names, vtype
        character(len=*), intent(in), optional :: also
        real(dp), intent(in), optional :: bound
        integer :: i, j
        i = 1
        do while (i <= len_trim(names))
            j = index(names(i:) // ' ', ' ') + i - 1
            if (present(bound) .and. vtype == 'R') then
                call c%key(names(i:j - 1), vtype, vmin=-bound, vmax=bound)
            else
                call c%key(names(i:j - 1), vtype)
            end if
            i = j + 1
        end do
        if (present(also)) then
            call c%rule(RULE_AU_MOINS_UN, names // ' ' // also)
        else
            call c%rule(RULE_AU_MOINS_UN, names)
        end if
    end subroutine add_components

end module catalog_loads
