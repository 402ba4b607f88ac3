!> The catalog of the model commands: AFFE_MODELE, AFFE_MATERIAU (LIRE_MAILLAGE:
!> catalog_mesh; DEFI_MATERIAU: catalog_materials).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_mesh_model
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_UN_PARMI, RULE_AU_MOINS_UN
    use number_limits, only: MAX_LENGTH, MAX_MODULUS, MIN_MODULUS
    use catalog_common, only: OUI_NON
    implicit none
    private
    public :: describe_mesh_and_model

contains

    subroutine describe_mesh_and_model(c)
        type(catalog_t), intent(inout) :: c
        call c%command('AFFE_MODELE', 'modele')
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%fact('AFFE', max=MANY, req=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('PHENOMENE', 'TXM', req=.true., into='MECANIQUE')
        call c%key('MODELISATION', 'TXM', max=MANY, req=.true., &
                   into='DKT D_PLAN C_PLAN DIS_T 2D_DIS_T DIS_TR 2D_DIS_TR')
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VERI_JACOBIEN', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('DISTRIBUTION', 'ANY', min=0, max=MANY, noop=.true.)

        call c%command('AFFE_MATERIAU', 'cham_mater')
        call c%key('MAILLAGE', 'maillage')
        call c%key('MODELE', 'modele')
        call c%rule(RULE_AU_MOINS_UN, 'MAILLAGE MODELE')
        call c%fact('AFFE', max=MANY, req=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('MATER', 'mater', max=MANY, req=.true.)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_mesh_and_model

end module catalog_mesh_model
