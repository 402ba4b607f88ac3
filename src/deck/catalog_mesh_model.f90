!> The catalog of the model commands: AFFE_MODELE, AFFE_MATERIAU (LIRE_MAILLAGE:
!> catalog_mesh; DEFI_MATERIAU: catalog_materials).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_mesh_model
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_UN_PARMI, RULE_AU_MOINS_UN, RULE_EXCLUS
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
        call describe_affe_varc(c)
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_mesh_and_model

    !> AFFE_MATERIAU/AFFE_VARC as Code_Aster's C_AFFE_VARC (c_affe_varc.py): NOM_VARC, the
    !> cells (TOUT or GROUP_MA; neither: every cell), CHAM_GD or EVOL (with NOM_CHAM,
    !> PROL_DROITE / PROL_GAUCHE = 'EXCLU', FONC_INST), VALE_REF required for TEMP and SECH.
    !> (elem's: the command variables, model_varc.)
    subroutine describe_affe_varc(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('AFFE_VARC', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'GROUP_MA TOUT')
        call c%key('NOM_VARC', 'TXM', req=.true., into='TEMP GEOM CORR IRRA HYDR SECH ' // &
                   'EPSA M_ACIER M_ZIRC NEUT1 NEUT2 NEUT3 PTOT')
        call c%key('CHAM_GD', 'CHAM_GD')
        call c%key('EVOL', 'RESU')
        call c%rule(RULE_UN_PARMI, 'EVOL CHAM_GD')
        call c%bloc(exists='EVOL')
        call c%key('NOM_CHAM', 'TXM', into='TEMP CORR IRRA NEUT GEOM HYDR_ELNO HYDR_NOEU ' // &
                   'META_ELNO META_NOEU EPSA_ELNO EPSA_NOEU PTOT HHO_TEMP SECH')
        call c%key('PROL_DROITE', 'TXM', def='EXCLU', into='CONSTANT LINEAIRE EXCLU')
        call c%key('PROL_GAUCHE', 'TXM', def='EXCLU', into='CONSTANT LINEAIRE EXCLU')
        call c%key('FONC_INST', 'FUNC')
        call c%end_bloc()
        call c%bloc(key='NOM_VARC', equals='TEMP SECH')
        call c%key('VALE_REF', 'R', req=.true., vmin=-MAX_MODULUS, vmax=MAX_MODULUS)
        call c%end_bloc()
        call c%end_fact()
    end subroutine describe_affe_varc

end module catalog_mesh_model
