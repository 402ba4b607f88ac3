!> The catalog of the table commands: CREA_TABLE, CALC_TABLE, RECU_TABLE, LIRE_TABLE,
!> TEST_TABLE, IMPR_TABLE, POST_RELEVE_T (issue 20). Part of THE command catalog (deck_catalog_data
!> gathers the parts): keywords, types, cardinality, defaults and rules as Code_Aster's
!> catalog gives them (code_aster/Cata/Commands/<command>.py; test_table takes
!> C_TEST_REFERENCE("TABLE") of Commons/c_test_reference.py).
!>
!> Code_Aster's catalog has conditional blocks (BLOC) this catalog does not: their
!> keywords are optional here, with their defaults, and the handler checks what the block
!> condition would (a VALE without a comparison, an OPERATION's own keywords...). Defaults
!> that are not lists of words (IMPR_TABLE SEPARATEUR=' ', FIN_LIGNE='\n') are applied by
!> the handler, which says so.
module catalog_tables
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, &
        RULE_PRESENT_PRESENT, RULE_PRESENT_ABSENT, RULE_ENSEMBLE
    use catalog_common, only: ANGLE_MAX
    use number_limits, only: MAX_LENGTH
    implicit none
    private
    public :: describe_tables

    !> Code_Aster's CRIT_COMP of FILTRE (TEST_TABLE, IMPR_TABLE, RECU_FONCTION); CALC_TABLE
    !> adds REGEXP.
    character(len=*), parameter :: CRIT_COMP = 'EQ LT GT NE LE GE VIDE NON_VIDE MAXI ' // &
        'MAXI_ABS MINI MINI_ABS'
    character(len=*), parameter, public :: TABLE_TYPE = 'table_sdaster'

contains

    subroutine describe_tables(c)
        type(catalog_t), intent(inout) :: c
        call describe_crea_table(c)
        call describe_calc_table(c)
        call describe_recu_table(c)
        call describe_lire_table(c)
        call describe_test_table(c)
        call describe_impr_table(c)
        call describe_post_releve_t(c)
        call describe_macr_lign_coupe(c)
        call describe_post_elem(c)
    end subroutine describe_tables

    !> POST_RELEVE_T (U4.81.21): values of fields along a list of nodes, their means,
    !> resultants and moments, in a chosen frame. Code_Aster's three blocks (EXTREMA,
    !> MOYENNE_ARITH, the others) share their keywords here; the rules of the last block
    !> (a node list, one quantity, ...) are checked by the handler for the operations it
    !> governs.
    subroutine describe_post_releve_t(c)
        type(catalog_t), intent(inout) :: c
        call c%command('POST_RELEVE_T', TABLE_TYPE)
        call c%fact('ACTION', max=MANY, req=.true.)
        call c%rule(RULE_UN_PARMI, 'RESULTAT CHAM_GD')
        call c%key('OPERATION', 'TXM', req=.true., max=2, &
                   into='EXTRACTION MOYENNE MOYENNE_ARITH EXTREMA')
        call c%key('INTITULE', 'TXM', req=.true.)
        call c%key('CHAM_GD', 'cham_no_sdaster|cham_elem')
        call c%key('RESULTAT', 'RESU')
        ! ---- RESULTAT: the field and the instants
        call c%key('NOM_CHAM', 'TXM')
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('LIST_ORDRE', 'listis')
        call c%key('NUME_MODE', 'I', max=MANY)
        call c%key('LIST_MODE', 'listis')
        call c%key('NOEUD_CMP', 'TXM', max=MANY)
        call c%key('NOM_CAS', 'TXM', max=MANY)
        call c%key('FREQ', 'R', max=MANY)
        call c%key('LIST_FREQ', 'listr8')
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE LIST_ORDRE NUME_MODE LIST_MODE ' // &
                    'INST LIST_INST FREQ LIST_FREQ NOEUD_CMP NOM_CAS')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        ! ---- where and what
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('MAILLE', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%key('TOUT_CMP', 'TXM', into='OUI')
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT_CMP NOM_CMP')
        call c%key('INVARIANT', 'TXM', into='OUI')
        call c%key('ELEM_PRINCIPAUX', 'TXM', into='OUI')
        call c%key('RESULTANTE', 'TXM', max=MANY, &
                   into='DX DY DZ NXX NYY NXY PRE1 PRE2 TEMP')
        call c%key('MOMENT', 'TXM', max=MANY, into='DRX DRY DRZ MXX MYY MXY')
        call c%key('POINT', 'R', max=MANY, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%rule(RULE_PRESENT_PRESENT, 'TRAC_DIR DIRECTION')
        call c%rule(RULE_ENSEMBLE, 'MOMENT POINT')
        call c%rule(RULE_PRESENT_PRESENT, 'MOMENT RESULTANTE')
        call c%rule(RULE_PRESENT_ABSENT, 'TOUT_CMP TRAC_DIR TRAC_NOR')
        call c%rule(RULE_EXCLUS, 'TRAC_DIR TRAC_NOR')
        call c%rule(RULE_PRESENT_PRESENT, 'ORIGINE AXE_Z')
        call c%key('REPERE', 'TXM', def='GLOBAL', &
                   into='GLOBAL LOCAL POLAIRE UTILISATEUR CYLINDRIQUE')
        call c%key('ANGL_NAUT', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ORIGINE', 'R', min=3, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('AXE_Z', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('TRAC_NOR', 'TXM', into='OUI')
        call c%key('TRAC_DIR', 'TXM', into='OUI')
        call c%key('DIRECTION', 'R', max=MANY, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('VECT_Y', 'R', max=MANY, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('MOYE_NOEUD', 'TXM', def='OUI', into='OUI NON')
        call c%key('FORMAT_C', 'TXM', def='MODULE', into='MODULE REEL IMAG')
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', max=MANY)
    end subroutine describe_post_releve_t

    !> One FILTRE factor keyword (TEST_TABLE, IMPR_TABLE): several values allowed when
    !> `several`.
    subroutine describe_filter(c, several)
        type(catalog_t), intent(inout) :: c
        logical, intent(in) :: several
        integer :: n
        n = 1
        if (several) n = MANY
        call c%fact('FILTRE', max=MANY)
        call c%key('NOM_PARA', 'TXM', req=.true.)
        call c%key('CRIT_COMP', 'TXM', def='EQ', into=CRIT_COMP)
        call c%key('VALE', 'R', max=n)
        call c%key('VALE_I', 'I', max=n)
        call c%key('VALE_K', 'TXM', max=n)
        call c%rule(RULE_EXCLUS, 'VALE VALE_I VALE_K')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)
        call c%end_fact()
    end subroutine describe_filter

    !> CREA_TABLE (U4.33.02): from lists, a function, or a result's field.
    subroutine describe_crea_table(c)
        type(catalog_t), intent(inout) :: c
        call c%command('CREA_TABLE', TABLE_TYPE)
        call c%rule(RULE_EXCLUS, 'FONCTION LISTE RESU')
        call c%fact('LISTE', max=MANY)
        call c%key('PARA', 'TXM', req=.true.)
        call c%key('TYPE_K', 'TXM', def='K8', into='K8 K16 K24')
        call c%key('NUME_LIGN', 'I', max=MANY, vmin=1.0_dp)
        call c%key('LISTE_I', 'I', max=MANY)
        call c%key('LISTE_R', 'R', max=MANY)
        call c%key('LISTE_K', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'LISTE_I LISTE_R LISTE_K')
        call c%end_fact()
        call c%fact('FONCTION')
        call c%key('FONCTION', 'fonction', req=.true.)
        call c%key('PARA', 'TXM', min=2, max=2)
        call c%end_fact()
        call c%fact('RESU')
        call c%key('CHAM_GD', 'cham_no_sdaster|cham_elem|carte_sdaster')
        call c%key('RESULTAT', 'RESU')
        call c%rule(RULE_UN_PARMI, 'CHAM_GD RESULTAT')
        ! the shells' characteristics place Code_Aster's Gauss-point coordinates across the
        ! thickness; parasol writes no coordinates for Gauss points
        call c%key('CARA_ELEM', 'cara_elem', noop=.true.)
        call c%key('INTITULE', 'TXM')
        call c%key('NOM_CHAM', 'TXM')
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST LIST_INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT_CMP', 'TXM', into='OUI')
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%key('NOM_VARI', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT_CMP NOM_CMP NOM_VARI')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT GROUP_MA GROUP_NO')
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_NO')
        call c%end_fact()
        call c%key('TYPE_TABLE', 'TXM', def='TABLE', into='TABLE TABLE_FONCTION TABLE_CONTAINER')
        call c%key('TITRE', 'TXM', max=MANY)
    end subroutine describe_crea_table

    !> CALC_TABLE (U4.33.03): a sequence of ACTION on a table. The keywords of every
    !> OPERATION's block sit together in ACTION (VALE is any value: reals for FILTRE,
    !> any type for AJOUT_LIGNE and AJOUT_COLONNE).
    subroutine describe_calc_table(c)
        type(catalog_t), intent(inout) :: c
        call c%command('CALC_TABLE', TABLE_TYPE)
        call c%key('TABLE', TABLE_TYPE, req=.true.)
        call c%fact('ACTION', max=MANY, req=.true.)
        call c%key('OPERATION', 'TXM', req=.true., into='FILTRE EXTR RENOMME TRI COMB ' // &
                   'AJOUT_LIGNE OPER SUPPRIME UNIQUE AJOUT_COLONNE STATISTIQUES CALCUL')
        call c%key('NOM_PARA', 'TXM', max=MANY)
        call c%key('CRIT_COMP', 'TXM', def='EQ', into=CRIT_COMP // ' REGEXP')
        call c%key('VALE', 'ANY', max=MANY)
        call c%key('VALE_I', 'I', max=MANY)
        call c%key('VALE_K', 'TXM', max=MANY)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)
        call c%key('ORDRE', 'TXM', def='CROISSANT', into='CROISSANT DECROISSANT')
        call c%key('TABLE', TABLE_TYPE)
        call c%key('RESTREINT', 'TXM', def='NON', into='OUI NON')
        call c%key('FORMAT_R', 'TXM')
        call c%key('FORMULE', 'formule')
        call c%key('NOM_COLONNE', 'TXM', max=MANY)
        call c%key('VALE_COLONNE', 'ANY', max=MANY)
        call c%key('TYPE_CALCUL', 'TXM', max=MANY, &
                   into='MAXI MINI SOMM MOY MAXI_ABS MINI_ABS SOMM_ABS')
        call c%end_fact()
        call c%key('TYPE_TABLE', 'TXM', into='TABLE TABLE_FONCTION TABLE_CONTAINER')
        call c%key('TITRE', 'TXM', max=MANY)
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_calc_table

    !> RECU_TABLE (U4.71.02): a result's parameters by NUME_ORDRE, or a table it holds.
    subroutine describe_recu_table(c)
        type(catalog_t), intent(inout) :: c
        call c%command('RECU_TABLE', TABLE_TYPE)
        call c%key('CO', 'RESU', req=.true.)
        call c%key('NOM_TABLE', 'TXM')
        call c%key('NOM_PARA', 'TXM', max=MANY)
        call c%key('TOUT_PARA', 'TXM', into='OUI')
        call c%rule(RULE_UN_PARMI, 'NOM_TABLE NOM_PARA TOUT_PARA')
        call c%key('TITRE', 'TXM', max=MANY)
    end subroutine describe_recu_table

    !> LIRE_TABLE (U7.02.03): a table from a text file (FORMAT ASTER, LIBRE, TABLEAU).
    subroutine describe_lire_table(c)
        type(catalog_t), intent(inout) :: c
        call c%command('LIRE_TABLE', TABLE_TYPE)
        call c%key('UNITE', 'I', req=.true., vmin=1.0_dp, vmax=99.0_dp)
        call c%key('FORMAT', 'TXM', def='TABLEAU', into='ASTER LIBRE TABLEAU')
        call c%key('NUME_TABLE', 'I', def='1', vmin=1.0_dp)
        call c%key('SEPARATEUR', 'TXM')
        call c%key('RENOMME_PARA', 'TXM', into='UNIQUE')
        call c%key('TITRE', 'TXM', max=MANY)
        call c%key('INFO', 'I', into='1 2')
    end subroutine describe_lire_table

    !> TEST_TABLE (U4.92.03): one cell (FILTRE leaves one row) or a column reduced by
    !> TYPE_TEST, against VALE_CALC (and VALE_REFE with REFERENCE).
    subroutine describe_test_table(c)
        type(catalog_t), intent(inout) :: c
        call c%command('TEST_TABLE', '')
        call c%key('TABLE', TABLE_TYPE, req=.true.)
        call describe_filter(c, .false.)
        call c%key('NOM_PARA', 'TXM', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VALE_CALC', 'R', max=MANY)
        call c%key('VALE_CALC_I', 'I', max=MANY)
        call c%key('VALE_CALC_K', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'VALE_CALC VALE_CALC_I VALE_CALC_K')
        call c%key('ORDRE_GRANDEUR', 'R', vmin=0.0_dp)
        call c%key('LEGENDE', 'TXM')
        call c%key('VALE_ABS', 'TXM', def='NON', into='OUI NON')
        call c%key('TYPE_TEST', 'TXM', into='SOMM_ABS SOMM MAX MIN')
        call c%key('TOLE_MACHINE', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('REFERENCE', 'TXM', into='ANALYTIQUE SOURCE_EXTERNE AUTRE_ASTER NON_DEFINI')
        call c%key('VALE_REFE', 'R', max=MANY)
        call c%key('VALE_REFE_I', 'I', max=MANY)
        call c%key('VALE_REFE_K', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'VALE_REFE VALE_REFE_I VALE_REFE_K')
        call c%key('PRECISION', 'R', def='1.0E-3', vmin=0.0_dp)
    end subroutine describe_test_table

    !> IMPR_TABLE (U4.91.03): a table in a text file (default unit 8, the .resu).
    subroutine describe_impr_table(c)
        type(catalog_t), intent(inout) :: c
        call c%command('IMPR_TABLE', '')
        call c%key('TABLE', TABLE_TYPE, req=.true.)
        call c%key('FORMAT', 'TXM', def='TABLEAU', &
                   into='TABLEAU ASTER TABLEAU_CROISE AGRAF XMGRACE NUMPY')
        call c%key('UNITE', 'I', def='8', vmin=1.0_dp, vmax=99.0_dp)
        call describe_filter(c, .true.)
        call c%fact('TRI')
        call c%key('NOM_PARA', 'TXM', max=MANY, req=.true.)
        call c%key('ORDRE', 'TXM', def='CROISSANT', into='CROISSANT DECROISSANT')
        call c%end_fact()
        call c%key('PAGINATION', 'TXM', max=MANY)
        call c%key('FORMAT_R', 'TXM', def='E12.5')
        call c%key('NOM_PARA', 'TXM', max=MANY)
        call c%key('IMPR_FONCTION', 'TXM', def='NON', into='OUI NON', noop=.true.)
        call c%key('DEBUT_TABLE', 'TXM')
        call c%key('FIN_TABLE', 'TXM')
        call c%key('SEPARATEUR', 'TXM')
        call c%key('COMMENTAIRE', 'TXM', def='#')
        call c%key('COMM_PARA', 'TXM')
        call c%key('DEBUT_LIGNE', 'TXM')
        call c%key('FIN_LIGNE', 'TXM')
        call c%key('TITRE', 'TXM', max=MANY)
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_impr_table

    !> MACR_LIGN_COUPE (U4.81.13; Cata/Commands/macr_lign_coupe.py): values of a result's
    !> field along cut lines. NOM_CHAM has no default here: Code_Aster's depends on the
    !> result's type (SIGM_NOEU mechanical, TEMP thermal), the handler applies it. The
    !> blocks of TYPE (SEGMENT, ARC, GROUP_NO, GROUP_MA) and REPERE are checked by the
    !> handler.
    subroutine describe_macr_lign_coupe(c)
        type(catalog_t), intent(inout) :: c
        call c%command('MACR_LIGN_COUPE', TABLE_TYPE)
        call c%rule(RULE_UN_PARMI, 'RESULTAT CHAM_GD')
        call c%key('RESULTAT', 'RESU')
        call c%key('CHAM_GD', 'cham_no_sdaster|cham_elem')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('NUME_MODE', 'I', max=MANY)
        call c%key('LIST_ORDRE', 'listis')
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'NUME_ORDRE NUME_MODE LIST_ORDRE INST LIST_INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('NOM_CHAM', 'TXM')
        call c%key('UNITE_MAILLAGE', 'I', noop=.true.)
        call c%key('MODELE', 'modele', noop=.true.)
        call c%fact('VIS_A_VIS', max=MANY)
        call c%rule(RULE_EXCLUS, 'GROUP_MA_1 MAILLE_1')
        call c%key('GROUP_MA_1', 'TXM')
        call c%key('MAILLE_1', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('LIGN_COUPE', max=MANY, req=.true.)
        call c%rule(RULE_EXCLUS, 'NOM_CMP INVARIANT ELEM_PRINCIPAUX RESULTANTE')
        call c%rule(RULE_PRESENT_PRESENT, 'TRAC_DIR DIRECTION')
        call c%rule(RULE_EXCLUS, 'TRAC_DIR TRAC_NOR')
        call c%rule(RULE_PRESENT_PRESENT, 'TRAC_DIR NOM_CMP')
        call c%rule(RULE_PRESENT_PRESENT, 'TRAC_NOR NOM_CMP')
        call c%rule(RULE_ENSEMBLE, 'MOMENT POINT')
        call c%key('INTITULE', 'TXM')
        call c%key('TYPE', 'TXM', def='SEGMENT', into='GROUP_NO SEGMENT ARC GROUP_MA')
        call c%key('REPERE', 'TXM', def='GLOBAL', &
                   into='GLOBAL LOCAL POLAIRE UTILISATEUR CYLINDRIQUE')
        call c%key('OPERATION', 'TXM', def='EXTRACTION', into='EXTRACTION MOYENNE')
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%key('INVARIANT', 'TXM', into='OUI')
        call c%key('ELEM_PRINCIPAUX', 'TXM', into='OUI')
        call c%key('TRAC_NOR', 'TXM', into='OUI')
        call c%key('TRAC_DIR', 'TXM', into='OUI')
        call c%key('DIRECTION', 'R', max=MANY, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('RESULTANTE', 'TXM', max=MANY, into='DX DY DZ NXX NYY NXY')
        call c%key('MOMENT', 'TXM', max=MANY, into='DRX DRY DRZ MXX MYY MXY')
        call c%key('POINT', 'R', max=MANY, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('VECT_Y', 'R', min=2, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ANGL_NAUT', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('GROUP_NO', 'TXM')
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLAGE', 'maillage')
        call c%key('GROUP_NO_ORIG', 'TXM')
        call c%key('GROUP_NO_EXTR', 'TXM')
        call c%key('VECT_ORIE', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('NB_POINTS', 'I', vmin=2.0_dp, vmax=1.0e5_dp)   ! parasol's bound
        call c%key('COOR_ORIG', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('COOR_EXTR', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%rule(RULE_EXCLUS, 'COOR_ORIG GROUP_NO_ORIG')
        call c%rule(RULE_EXCLUS, 'COOR_EXTR GROUP_NO_EXTR')
        call c%key('CENTRE', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('ANGLE', 'R', vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('DNOR', 'R', min=2, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ORIGINE', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('AXE_Z', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('DISTANCE_MAX', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%key('DISTANCE_ALARME', 'R', vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%end_fact()
    end subroutine describe_macr_lign_coupe

    !> POST_ELEM (U4.81.22; Cata/Commands/post_elem.py): MASS_INER and the keywords of its
    !> block; ENER_POT, TRAV_EXT, MINMAX, INTEGRALE and VOLUMOGRAMME (the ones the issue and
    !> the decks name) are declared so that the handler can say they are not built. Blocks
    !> are checked by the handler.
    subroutine describe_post_elem(c)
        type(catalog_t), intent(inout) :: c
        call c%command('POST_ELEM', TABLE_TYPE)
        call c%rule(RULE_UN_PARMI, 'MASS_INER ENER_POT TRAV_EXT MINMAX INTEGRALE VOLUMOGRAMME')
        call c%fact('MASS_INER', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA MAILLE')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('MAILLE', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('ORIG_INER', 'R', min=3, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%end_fact()
        call c%fact('ENER_POT', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('TRAV_EXT')
        call c%end_fact()
        call c%fact('MINMAX', max=MANY)
        call c%rule(RULE_UN_PARMI, 'CHAM_GD RESULTAT')
        call c%rule(RULE_PRESENT_PRESENT, 'CHAM_GD MODELE')
        call c%rule(RULE_PRESENT_PRESENT, 'RESULTAT NOM_CHAM')
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE LIST_ORDRE INST LIST_INST')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('RESULTAT', 'RESU')
        call c%key('NOM_CHAM', 'TXM')
        call c%key('CHAM_GD', 'cham_no_sdaster|cham_elem')
        call c%key('MODELE', 'modele')
        call c%key('NOM_CMP', 'TXM', max=MANY, req=.true.)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('LIST_ORDRE', 'listis')
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%end_fact()
        call c%fact('INTEGRALE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('MAILLE', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('NOM_CHAM', 'TXM')
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%key('NOM_VARI', 'TXM', max=MANY)
        call c%key('DEJA_INTEGRE', 'TXM', into='OUI NON')
        call c%key('TYPE_MAILLE', 'TXM', req=.true., into='1D 2D 3D')
        call c%end_fact()
        call c%fact('VOLUMOGRAMME', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%rule(RULE_UN_PARMI, 'NB_INTERV SEUIL')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%key('TYPE_MAILLE', 'TXM', into='2D 3D')
        call c%key('NOM_CHAM', 'TXM')
        call c%key('NOM_CMP', 'TXM', req=.true.)
        call c%key('NB_INTERV', 'I')
        call c%key('SEUIL', 'R', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('BORNES', 'R', min=2, max=2)
        call c%key('NORME', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%end_fact()
        call c%key('MODELE', 'modele')
        call c%key('CHAM_MATER', 'cham_mater')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%key('NUME_COUCHE', 'I', def='1', vmin=1.0_dp)
        call c%key('NIVE_COUCHE', 'TXM', def='MOY', into='INF SUP MOY')
        call c%key('MODE_FOURIER', 'I', def='0')
        call c%key('GEOMETRIE', 'TXM', def='INITIALE', into='INITIALE DEFORMEE')
        call c%key('ANGLE', 'I', def='0')
        call c%key('CHAM_GD', 'cham_no_sdaster|cham_elem')
        call c%key('RESULTAT', 'RESU')
        call c%rule(RULE_EXCLUS, 'CHAM_GD RESULTAT')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('LIST_ORDRE', 'listis')
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%key('FREQ', 'R', max=MANY)
        call c%key('LIST_FREQ', 'listr8')
        call c%key('NUME_MODE', 'I', max=MANY)
        call c%key('NOEUD_CMP', 'TXM', min=2, max=2)
        call c%key('NOM_CAS', 'TXM')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE LIST_ORDRE INST LIST_INST FREQ ' // &
                    'LIST_FREQ NUME_MODE NOEUD_CMP NOM_CAS')
        call c%key('TITRE', 'TXM', max=MANY)
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_post_elem

end module catalog_tables
