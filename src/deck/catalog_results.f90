!> The catalog of the commands that test and print results: TEST_RESU, IMPR_RESU.
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_results
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN
    use catalog_common, only: OUI_NON
    use catalog_fields, only: NOM_CHAM_NAMES
    implicit none
    private
    public :: describe_outputs

contains

    subroutine describe_outputs(c)
        type(catalog_t), intent(inout) :: c
        ! Code_Aster's TEST_RESU (code_aster/Cata/Commands/test_resu.py, U4.92.01) for the
        ! objects parasol has: fields of CREA_CHAMP (CHAM_NO, CARTE, CHAM_ELEM), fields and
        ! parameters of results (RESU), counts of a mesh (MAILLAGE)
        call c%command('TEST_RESU', '')
        call c%rule(RULE_AU_MOINS_UN, 'CHAM_NO CARTE CHAM_ELEM RESU MAILLAGE')
        call c%fact('CHAM_NO', max=MANY)
        call c%key('CHAM_GD', 'cham_no_sdaster', req=.true.)
        call c%key('GROUP_NO', 'TXM')
        call c%key('NOEUD', 'TXM')
        call c%rule(RULE_EXCLUS, 'GROUP_NO NOEUD')
        call c%key('NOM_CMP', 'TXM')
        call test_reference_keys(c, 'CHAM_NO')
        call c%end_fact()
        call c%fact('CARTE', max=MANY)
        call c%key('CHAM_GD', 'carte_sdaster', req=.true.)
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLE', 'TXM')
        call c%rule(RULE_UN_PARMI, 'GROUP_MA MAILLE')
        call c%key('NOM_CMP', 'TXM', req=.true.)
        call test_reference_keys(c, 'CARTE')
        call c%end_fact()
        call c%fact('CHAM_ELEM', max=MANY)
        call c%key('CHAM_GD', 'cham_elem', req=.true.)
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLE', 'TXM')
        call c%rule(RULE_EXCLUS, 'GROUP_MA MAILLE')
        call c%key('POINT', 'I')
        call c%key('SOUS_POINT', 'I')
        call c%key('GROUP_NO', 'TXM')
        call c%key('NOEUD', 'TXM')
        call c%rule(RULE_EXCLUS, 'GROUP_NO NOEUD POINT')
        call c%key('NOM_CMP', 'TXM')
        call test_reference_keys(c, 'CHAM_ELEM')
        call c%end_fact()
        call c%fact('RESU', max=MANY)
        call c%key('RESULTAT', 'RESU', req=.true.)
        call c%key('INST', 'R')
        call c%key('NUME_ORDRE', 'I')
        call c%rule(RULE_UN_PARMI, 'INST NUME_ORDRE')
        call c%key('PARA', 'TXM')
        call c%key('NOM_CHAM', 'TXM', into=NOM_CHAM_NAMES)
        call c%rule(RULE_UN_PARMI, 'NOM_CHAM PARA')
        call c%key('NOM_CMP', 'TXM')
        call c%key('NOM_VARI', 'TXM')
        call c%rule(RULE_EXCLUS, 'NOM_CMP NOM_VARI PARA')
        call c%key('GROUP_NO', 'TXM')
        call c%key('NOEUD', 'TXM')
        call c%rule(RULE_EXCLUS, 'GROUP_NO NOEUD')
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLE', 'TXM')
        call c%rule(RULE_EXCLUS, 'GROUP_MA MAILLE')
        call c%rule(RULE_EXCLUS, 'GROUP_NO POINT')
        call c%key('POINT', 'I')
        call c%key('SOUS_POINT', 'I')
        call test_reference_keys(c, 'RESU')
        call c%end_fact()
        call c%fact('MAILLAGE', max=MANY)
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%key('CARA', 'TXM', req=.true., into='NB_MAILLE NB_NOEUD NB_GROUP_MA ' // &
            'NB_GROUP_NO NB_MA_GROUP_MA NB_NO_GROUP_NO')
        call c%key('NOM_GROUP_MA', 'TXM')
        call c%key('NOM_GROUP_NO', 'TXM')
        call test_reference_keys(c, 'MAILLAGE')
        call c%end_fact()

        ! Code_Aster's IMPR_RESU (code_aster/Cata/Commands/impr_resu.py, U4.91.01): the
        ! keywords of the formats parasol writes (RESULTAT, MED, GMSH and parasol's VTK),
        ! in one RESU factor; the default FORMAT stays parasol's RESULTAT
        call c%command('IMPR_RESU', '')
        call c%key('FORMAT', 'TXM', def='RESULTAT', into='RESULTAT GMSH VTK MED')
        call c%key('UNITE', 'I', def='8')
        call c%key('MODELE', 'modele', noop=.true.)
        call c%key('PROC0', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('VERSION_MED', 'TXM', into='3.3.1 4.0.0 4.1.0', noop=.true.)
        call c%key('FICHIER_UNIQUE', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('INFO', 'I', def='1', into='1 2', noop=.true.)
        call c%fact('RESU', max=MANY, req=.true.)
        call c%rule(RULE_AU_MOINS_UN, 'CHAM_GD RESULTAT MAILLAGE')
        call c%rule(RULE_EXCLUS, 'CHAM_GD RESULTAT')
        call c%rule(RULE_EXCLUS, 'TOUT_CMP NOM_CMP')
        call c%rule(RULE_EXCLUS, 'TOUT_CHAM NOM_CHAM')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST LIST_INST')
        call c%key('MAILLAGE', 'maillage')
        call c%key('CARA_ELEM', 'cara_elem', noop=.true.)
        call c%key('CHAM_GD', 'CHAM_GD')
        call c%key('RESULTAT', 'RESU')
        call c%key('TOUT_CHAM', 'TXM', into=OUI_NON)
        call c%key('NOM_CHAM', 'TXM', max=MANY, into=NOM_CHAM_NAMES)
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT_CMP', 'TXM', into='OUI')
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('IMPR_COOR', 'TXM', def='NON', into=OUI_NON)
        call c%key('VALE_MAX', 'TXM', into='OUI')
        call c%key('VALE_MIN', 'TXM', into='OUI')
        call c%key('BORNE_INF', 'R')
        call c%key('BORNE_SUP', 'R')
        call c%key('FORMAT_R', 'TXM', def='1PE21.14', noop=.true.)
        call c%key('SOUS_TITRE', 'TXM')
        call c%key('INFO_MAILLAGE', 'TXM', def='NON', into=OUI_NON, noop=.true.)
        call c%key('IMPR_NOM_VARI', 'TXM', def='OUI', into=OUI_NON, noop=.true.)
        call c%key('VISU_SP', 'TXM', into='NON', noop=.true.)
        call c%end_fact()
    end subroutine describe_outputs

    !> The keywords of a tested value (Code_Aster's C_TEST_REFERENCE,
    !> code_aster/Cata/Commons/c_test_reference.py), for the factor keyword `group`: the
    !> computed values VALE_CALC (VALE_CALC_I), TOLE_MACHINE (default 1e-6; RESU: a second
    !> value is the precision of the instant), CRITERE (RELATIF; RESU: a second value for
    !> the instant), ORDRE_GRANDEUR, LEGENDE, VALE_ABS (not for CARTE), TYPE_TEST (not for
    !> CARTE), REFERENCE with VALE_REFE (VALE_REFE_I) and PRECISION (default 1e-3).
    subroutine test_reference_keys(c, group)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: group
        logical :: multi
        integer :: n_max
        multi = group == 'RESU'
        n_max = 1
        if (group /= 'CARTE' .and. group /= 'MAILLAGE') n_max = MANY
        if (group /= 'MAILLAGE') then
            call c%key('VALE_CALC', 'R', max=n_max)
            call c%key('VALE_REFE', 'R', max=n_max)
        end if
        call c%key('VALE_CALC_I', 'I', max=n_max)
        call c%key('VALE_REFE_I', 'I', max=n_max)
        if (group == 'MAILLAGE') then
            call c%rule(RULE_UN_PARMI, 'VALE_CALC_I')
        else
            call c%rule(RULE_UN_PARMI, 'VALE_CALC VALE_CALC_I')
        end if
        call c%rule(RULE_EXCLUS, 'VALE_REFE VALE_REFE_I')
        call c%key('ORDRE_GRANDEUR', 'R', vmin=0.0_dp)
        call c%key('LEGENDE', 'TXM')
        if (group /= 'CARTE') then
            call c%key('VALE_ABS', 'TXM', def='NON', into=OUI_NON)
            call c%key('TYPE_TEST', 'TXM', into='SOMM_ABS SOMM MAX MIN')
        end if
        if (multi) then
            call c%key('TOLE_MACHINE', 'R', max=2, vmin=0.0_dp)   ! Code_Aster: 1e-6 each
            call c%key('CRITERE', 'TXM', max=2, into='RELATIF ABSOLU')
        else
            call c%key('TOLE_MACHINE', 'R', def='1.0E-6', vmin=0.0_dp)
            call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        end if
        call c%key('REFERENCE', 'TXM', into='ANALYTIQUE SOURCE_EXTERNE AUTRE_ASTER NON_DEFINI')
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)    ! Code_Aster default
    end subroutine test_reference_keys

end module catalog_results
