!> The catalog of the commands that test and print results: TEST_RESU, IMPR_RESU.
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_results
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI
    use catalog_common, only: OUI_NON, RESULT_COMPONENTS
    implicit none
    private
    public :: describe_outputs

contains

    subroutine describe_outputs(c)
        type(catalog_t), intent(inout) :: c
        call c%command('TEST_RESU', '')
        call c%fact('RESU', max=MANY, req=.true.)
        call c%key('RESULTAT', 'RESU', req=.true.)
        call c%key('INST', 'R')
        call c%key('NUME_ORDRE', 'I')
        call c%rule(RULE_UN_PARMI, 'INST NUME_ORDRE')
        ! nodal fields at GROUP_NO / NOEUD; the spring fields (SIEF_ELGA, VARI_ELGA) at a
        ! cell (GROUP_MA of one cell, or MAILLE) and POINT (test_resu_command)
        call c%key('NOM_CHAM', 'TXM', req=.true., &
                   into='DEPL FORC_NODA REAC_NODA SIEF_ELGA VARI_ELGA')
        call c%key('NOM_CMP', 'TXM', req=.true., into=RESULT_COMPONENTS)
        call c%key('GROUP_NO', 'TXM')
        call c%key('NOEUD', 'TXM')
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLE', 'TXM')
        call c%rule(RULE_UN_PARMI, 'GROUP_NO NOEUD GROUP_MA MAILLE')
        call c%key('POINT', 'I')
        call c%key('VALE_CALC', 'R', req=.true.)
        call c%key('TOLE_MACHINE', 'R', def='1.0E-6', vmin=0.0_dp)     ! Code_Aster default
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('REFERENCE', 'TXM', into='ANALYTIQUE SOURCE_EXTERNE AUTRE_ASTER NON_DEFINI')
        call c%key('VALE_REFE', 'R')
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)        ! Code_Aster default
        call c%key('LEGENDE', 'TXM')
        call c%key('VALE_ABS', 'TXM', into=OUI_NON, noop=.true.)
        call c%end_fact()

        call c%command('IMPR_RESU', '')
        call c%key('FORMAT', 'TXM', def='RESULTAT', into='RESULTAT GMSH VTK MED')
        call c%key('UNITE', 'I', def='8')
        call c%key('MODELE', 'modele', noop=.true.)
        call c%key('PROC0', 'TXM', into=OUI_NON, noop=.true.)
        call c%fact('RESU', max=MANY, req=.true.)
        call c%key('RESULTAT', 'RESU', req=.true.)
        call c%key('NOM_CHAM', 'TXM', max=MANY, &
                   into='DEPL FORC_NODA REAC_NODA SIEF_ELGA VARI_ELGA')
        call c%key('INST', 'R', max=MANY)
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%rule(RULE_EXCLUS, 'INST NUME_ORDRE')
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOM_CMP', 'TXM', max=MANY, into=RESULT_COMPONENTS)
        call c%end_fact()
    end subroutine describe_outputs

end module catalog_results
