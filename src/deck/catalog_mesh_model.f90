!> The catalog of the mesh and model commands: LIRE_MAILLAGE, AFFE_MODELE, DEFI_MATERIAU,
!> AFFE_MATERIAU.
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
        call c%command('LIRE_MAILLAGE', 'maillage')
        call c%key('FORMAT', 'TXM', def='MED', into='ASTER MED GMSH')
        call c%key('UNITE', 'I', def='20')
        call c%key('NOM_MED', 'TXM')
        call c%key('INFO_MED', 'I', noop=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VERI_MAIL', 'ANY', min=0, max=MANY, noop=.true.)

        call c%command('AFFE_MODELE', 'modele')
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%fact('AFFE', max=MANY, req=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('PHENOMENE', 'TXM', req=.true., into='MECANIQUE')
        call c%key('MODELISATION', 'TXM', max=MANY, req=.true., &
                   into='DKT D_PLAN C_PLAN DIS_T 2D_DIS_T')
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VERI_JACOBIEN', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('DISTRIBUTION', 'ANY', min=0, max=MANY, noop=.true.)

        call c%command('DEFI_MATERIAU', 'mater', reentrant='f:MATER')
        call c%fact('ELAS')
        call c%key('E', 'R', req=.true., vmin=0.0_dp, vmax=MAX_MODULUS, &
                   vtiny=MIN_MODULUS)                   ! val_min 0; E > 0: the handler
        call c%key('NU', 'R', req=.true., vmin=-1.0_dp, vmax=0.5_dp)
        call c%key('RHO', 'R')
        call c%key('ALPHA', 'R', noop=.true.)
        call c%key('AMOR_ALPHA', 'R', noop=.true.)
        call c%key('AMOR_BETA', 'R', noop=.true.)
        call c%end_fact()
        call c%fact('DIS_CONTACT')
        call c%key('RIGI_NOR', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('RIGI_TAN', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_MODULUS, &
                   vtiny=MIN_MODULUS)
        call c%key('DIST_1', 'R', def='0.0', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('DIST_2', 'R', def='0.0', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('JEU', 'R', def='0.0', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('COULOMB', 'R', def='0.0', vmin=0.0_dp)
        call c%key('AMOR_NOR', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_MODULUS)
        call c%key('AMOR_TAN', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_MODULUS)
        call c%end_fact()
        call c%rule(RULE_AU_MOINS_UN, 'ELAS DIS_CONTACT')
        call c%key('INFO', 'I', def='1', into='1 2')

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
