!> The catalog of the commands on functions made from results (issue 20): RECU_FONCTION,
!> CALC_FONCTION, TEST_FONCTION, IMPR_FONCTION. Part of THE command catalog
!> (deck_catalog_data gathers the parts), as Code_Aster's catalog gives them
!> (code_aster/Cata/Commands/<command>.py; TEST_FONCTION takes C_TEST_REFERENCE("FONCTION")).
!> Conditional blocks are flattened as in catalog_tables: their keywords are optional here
!> and the handlers check what the block conditions would.
module catalog_result_functions
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, &
        RULE_PRESENT_PRESENT
    implicit none
    private
    public :: describe_result_functions

    !> Code_Aster's C_PARA_FONCTION: the parameter names a function may have.
    character(len=*), parameter, public :: PARA_FONCTION = 'DX DY DZ DRX DRY DRZ DTAN TEMP ' // &
        'TSEC INST X Y Z EPSI META FREQ PULS DSP AMOR ABSC SIGM HYDR SECH PORO SAT IRRA ' // &
        'PGAZ PCAP PLIQ PVAP PAD VITE ENDO NORM EPAIS EXCENT NEUT1 NEUT2 NEUT3 NEUT4 XF YF ' // &
        'ZF NUME_ORDRE'
    character(len=*), parameter :: PROL = 'CONSTANT LINEAIRE EXCLU'
    character(len=*), parameter :: CRIT_COMP = 'EQ LT GT NE LE GE VIDE NON_VIDE MAXI ' // &
        'MAXI_ABS MINI MINI_ABS'

contains

    subroutine describe_result_functions(c)
        type(catalog_t), intent(inout) :: c
        call describe_recu_fonction(c)
        call describe_calc_fonction(c)
        call describe_test_fonction(c)
        call describe_impr_fonction(c)
    end subroutine describe_result_functions

    !> The attributes a function command may set on its result.
    subroutine describe_attributes(c)
        type(catalog_t), intent(inout) :: c
        call c%key('NOM_PARA', 'TXM', into=PARA_FONCTION)
        call c%key('NOM_RESU', 'TXM')
        call c%key('INTERPOL', 'TXM', max=2, into='LIN LOG')
        call c%key('PROL_DROITE', 'TXM', into=PROL)
        call c%key('PROL_GAUCHE', 'TXM', into=PROL)
        call c%key('TITRE', 'TXM', max=MANY)
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_attributes

    !> RECU_FONCTION (U4.32.03): a function from a result's field over the instants, or
    !> from two columns of a table.
    subroutine describe_recu_fonction(c)
        type(catalog_t), intent(inout) :: c
        call c%command('RECU_FONCTION', 'fonction')
        call c%key('RESULTAT', 'RESU')
        call c%key('TABLE', 'table_sdaster')
        call c%key('CHAM_GD', 'cham_no_sdaster|cham_elem')
        call c%rule(RULE_UN_PARMI, 'RESULTAT TABLE CHAM_GD')
        ! ---- RESULTAT: the instants
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('TOUT_INST', 'TXM', into='OUI')
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('INTERP_NUME', 'TXM', into='NON LIN')
        ! ---- RESULTAT: the field and where
        call c%key('NOM_CHAM', 'TXM')
        call c%key('NOM_PARA_RESU', 'TXM')
        call c%key('NOM_CMP', 'TXM')
        call c%key('NOM_VARI', 'TXM')
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLE', 'TXM')
        call c%key('NOEUD', 'TXM')
        call c%key('GROUP_NO', 'TXM')
        call c%rule(RULE_EXCLUS, 'GROUP_NO NOEUD')
        call c%key('POINT', 'I', vmin=1.0_dp)
        call c%key('SOUS_POINT', 'I', vmin=1.0_dp)
        ! ---- TABLE
        call c%key('PARA_X', 'TXM')
        call c%key('PARA_Y', 'TXM')
        call c%rule(RULE_PRESENT_PRESENT, 'PARA_X PARA_Y')
        call c%key('NOM_PARA_TABL', 'TXM', into='FONCTION FONCTION_C')
        call c%fact('FILTRE', max=MANY)
        call c%key('NOM_PARA', 'TXM', req=.true.)
        call c%key('CRIT_COMP', 'TXM', def='EQ', into=CRIT_COMP)
        call c%key('VALE', 'R')
        call c%key('VALE_I', 'I')
        call c%key('VALE_K', 'TXM')
        call c%rule(RULE_EXCLUS, 'VALE VALE_I VALE_K')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)
        call c%end_fact()
        call describe_attributes(c)
    end subroutine describe_recu_fonction

    !> CALC_FONCTION (U4.32.04): the operations on functions parasol builds (COMB, MULT,
    !> DERIVE, INTEGRE, ABS, INVERSE, PUISSANCE, ENVELOPPE).
    subroutine describe_calc_fonction(c)
        type(catalog_t), intent(inout) :: c
        call c%command('CALC_FONCTION', 'fonction')
        call c%rule(RULE_UN_PARMI, 'DERIVE INTEGRE COMB MULT INVERSE ABS ENVELOPPE PUISSANCE')
        call c%fact('DERIVE')
        call c%key('METHODE', 'TXM', def='DIFF_CENTREE', into='DIFF_CENTREE')
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%end_fact()
        call c%fact('INTEGRE')
        call c%key('METHODE', 'TXM', def='TRAPEZE', into='SIMPSON TRAPEZE')
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%key('COEF', 'R', def='0.0')
        call c%end_fact()
        call c%fact('COMB', max=MANY)
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%key('COEF', 'R', req=.true.)
        call c%end_fact()
        call c%fact('MULT', max=MANY)
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%end_fact()
        call c%fact('INVERSE')
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%end_fact()
        call c%fact('ABS')
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%end_fact()
        call c%fact('ENVELOPPE')
        call c%key('FONCTION', 'fonction', max=MANY, req=.true.)
        call c%key('CRITERE', 'TXM', def='SUP', into='SUP INF')
        call c%end_fact()
        call c%fact('PUISSANCE')
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%key('EXPOSANT', 'I', def='1')
        call c%end_fact()
        call c%key('LIST_PARA', 'listr8')
        call describe_attributes(c)
    end subroutine describe_calc_fonction

    !> TEST_FONCTION (U4.92.02): values of functions, and their attributes.
    subroutine describe_test_fonction(c)
        type(catalog_t), intent(inout) :: c
        call c%command('TEST_FONCTION', '')
        call c%rule(RULE_AU_MOINS_UN, 'VALEUR ATTRIBUT')
        call c%fact('VALEUR', max=MANY)
        call c%key('FONCTION', 'fonction|formule', req=.true.)
        call c%key('NOM_PARA', 'TXM', max=2)
        call c%key('VALE_PARA', 'R', max=2)
        call c%key('INTERVALLE', 'R', min=2, max=2)
        call c%rule(RULE_UN_PARMI, 'VALE_PARA INTERVALLE')
        call c%key('VALE_CALC', 'R', max=MANY, req=.true.)
        call c%key('ORDRE_GRANDEUR', 'R', vmin=0.0_dp, noop=.true.)
        call c%key('LEGENDE', 'TXM')
        call c%key('VALE_ABS', 'TXM', def='NON', into='OUI NON')
        call c%key('TYPE_TEST', 'TXM', into='SOMM_ABS SOMM MAX MIN', noop=.true.)
        call c%key('TOLE_MACHINE', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('REFERENCE', 'TXM', into='ANALYTIQUE SOURCE_EXTERNE AUTRE_ASTER NON_DEFINI')
        call c%key('VALE_REFE', 'R', max=MANY)
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)
        call c%end_fact()
        call c%fact('ATTRIBUT', max=MANY)
        call c%key('FONCTION', 'fonction|formule', req=.true.)
        call c%key('PARA', 'R')
        call c%key('CRIT_PARA', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PREC_PARA', 'R', def='1.0E-3', vmin=0.0_dp)
        call c%key('ATTR', 'TXM', req=.true., into='NOM_PARA NOM_RESU PROL_DROITE ' // &
                   'PROL_GAUCHE INTERPOL PROL_GAUCHE_FONC PROL_DROITE_FONC INTERPOL_FONC ' // &
                   'NOM_PARA_FONC')
        call c%key('ATTR_REFE', 'TXM', req=.true.)
        call c%key('REFERENCE', 'TXM', into='ANALYTIQUE SOURCE_EXTERNE AUTRE_ASTER')
        call c%end_fact()
    end subroutine describe_test_fonction

    !> IMPR_FONCTION (U4.33.01): functions in a file for a curve plotter.
    subroutine describe_impr_fonction(c)
        type(catalog_t), intent(inout) :: c
        call c%command('IMPR_FONCTION', '')
        call c%key('FORMAT', 'TXM', def='TABLEAU', into='TABLEAU AGRAF XMGRACE LISS_ENVELOP')
        call c%key('UNITE', 'I', vmin=1.0_dp, vmax=99.0_dp)
        call c%key('UNITE_DIGR', 'I', def='26', vmin=1.0_dp, vmax=99.0_dp)
        call c%key('PILOTE', 'TXM')
        call c%fact('COURBE', max=MANY, req=.true.)
        call c%key('FONCTION', 'fonction|formule')
        call c%key('LIST_RESU', 'listr8')
        call c%key('FONC_X', 'fonction|formule')
        call c%key('FONC_Y', 'fonction|formule')
        call c%key('ABSCISSE', 'R', max=MANY)
        call c%key('ORDONNEE', 'R', max=MANY)
        call c%rule(RULE_UN_PARMI, 'FONCTION LIST_RESU FONC_X ABSCISSE')
        call c%key('LIST_PARA', 'listr8')
        call c%key('LEGENDE', 'TXM')
        call c%key('STYLE', 'I', vmin=0.0_dp)
        call c%key('COULEUR', 'I', vmin=0.0_dp)
        call c%key('MARQUEUR', 'I', vmin=0.0_dp)
        call c%key('FREQ_MARQUEUR', 'I', def='0')
        call c%key('TRI', 'TXM', def='N', into='N X Y XY YX')
        call c%end_fact()
        call c%key('TITRE', 'TXM')
        call c%key('SOUS_TITRE', 'TXM')
        call c%key('SEPARATEUR', 'TXM')
        call c%key('COMMENTAIRE', 'TXM', def='#')
        call c%key('COMM_PARA', 'TXM')
        call c%key('DEBUT_LIGNE', 'TXM')
        call c%key('FIN_LIGNE', 'TXM')
        call c%key('FORMAT_R', 'TXM', def='E12.5')
        call c%key('BORNE_X', 'R', min=2, max=2)
        call c%key('BORNE_Y', 'R', min=2, max=2)
        call c%key('ECHELLE_X', 'TXM', def='LIN', into='LIN LOG')
        call c%key('ECHELLE_Y', 'TXM', def='LIN', into='LIN LOG')
        call c%key('GRILLE_X', 'R', vmin=0.0_dp)
        call c%key('GRILLE_Y', 'R', vmin=0.0_dp)
        call c%key('LEGENDE_X', 'TXM')
        call c%key('LEGENDE_Y', 'TXM')
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_impr_fonction

end module catalog_result_functions
