!> The catalog of the load commands: AFFE_CHAR_MECA(_F), AFFE_CHAR_CINE(_F).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_loads
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN
    use number_limits, only: MAX_LENGTH
    use catalog_common, only: OUI_NON
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
    !> from the system (no Lagrange multipliers), MECA_IMPO only; NOEUD in the real form only.
    subroutine describe_kinematic_load(c, name, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, vtype
        call c%command(name, 'char_cine_meca')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%fact('MECA_IMPO', max=MANY, req=.true.)
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
        call c%fact('DDL_IMPO', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_NO GROUP_MA NOEUD')
        call c%key('BLOCAGE', 'TXM', max=2, into='DEPLACEMENT ROTATION')
        call add_components(c, DOFS, vtype, also='BLOCAGE', bound=MAX_LENGTH)  ! lengths, angles
        call c%end_fact()
        call c%fact('FORCE_NODALE', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'GROUP_NO NOEUD')
        call add_components(c, 'FX FY FZ MX MY MZ', vtype)
        call c%end_fact()
        call c%fact('FORCE_COQUE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call add_components(c, 'PRES FX FY FZ', vtype)
        call c%rule(RULE_EXCLUS, 'PRES FX')
        call c%rule(RULE_EXCLUS, 'PRES FY')
        call c%rule(RULE_EXCLUS, 'PRES FZ')
        call c%end_fact()
        call c%fact('PRES_REP', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%key('PRES', vtype, req=.true.)
        call c%end_fact()
        call c%fact('FORCE_CONTOUR', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call add_components(c, 'FX FY', vtype)
        call c%end_fact()
    end subroutine describe_load_command

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
