!> The catalog of the commands that make and transform fields: CREA_CHAMP, CALC_CHAMP,
!> POST_CHAMP, CREA_RESU (doc/architecture.md, "Fields and results"). Part of THE command
!> catalog (deck_catalog_data gathers the parts): keywords, types, cardinality, defaults
!> mirroring Code_Aster's (code_aster/Cata/Commands/<command>.py and its U4 documents),
!> allowed values and rules, as data.
module catalog_fields
    use kinds, only: dp
    implicit none
    private

    !> The field names of Code_Aster's results (code_aster/Cata/Commons/c_nom_cham_into.py,
    !> C_NOM_CHAM_INTO): what NOM_CHAM accepts in TEST_RESU, IMPR_RESU, CREA_CHAMP EXTR...
    !> A name parasol does not compute is refused when the command runs, naming what the
    !> result holds.
    character(len=*), parameter, public :: NOM_CHAM_NAMES = &
        'EFGE_ELGA EFGE_ELNO EGRU_ELNO EFGE_NOEU SIEF_ELGA SIEF_ELNO SIMY_ELGA SIEF_NOEU ' // &
        'SIGM_ELGA SIGM_ELNO SIGM_NOEU SIPM_ELNO SIPO_ELNO SIPO_NOEU SIRO_ELEM STRX_ELGA ' // &
        'DEGE_ELGA DEGE_ELNO DEGE_NOEU EPFD_ELGA EPFD_ELNO EPFD_NOEU EPFP_ELGA EPFP_ELNO ' // &
        'EPFP_NOEU EPME_ELGA EPME_ELNO EPME_NOEU EPMG_ELGA EPMG_ELNO EPMG_NOEU EPSG_ELGA ' // &
        'EPSG_ELNO EPSG_NOEU EPSI_ELGA EPSI_ELNO EPSI_NOEU EPSP_ELGA EPSP_ELNO EPSP_NOEU ' // &
        'EPVC_ELGA EPVC_ELNO EPVC_NOEU EPSL_ELGA EPSL_ELNO EPSL_NOEU DISS_ELEM DISS_ELGA ' // &
        'DISS_ELNO DISS_NOEU ECIN_ELEM ENEL_ELEM ENEL_ELGA ENEL_ELNO ENEL_NOEU ENTR_ELEM ' // &
        'EPOT_ELEM ETOT_ELEM ETOT_ELGA ETOT_ELNO ETOT_NOEU DERA_ELGA DERA_ELNO DERA_NOEU ' // &
        'ENDO_ELGA ENDO_ELNO ENDO_NOEU EPEQ_ELGA EPEQ_ELNO EPEQ_NOEU EPGQ_ELGA EPGQ_ELNO ' // &
        'EPGQ_NOEU EPMQ_ELGA EPMQ_ELNO EPMQ_NOEU INDL_ELGA PDIL_ELGA SIEQ_ELGA SIEQ_ELNO ' // &
        'SIEQ_NOEU VARC_ELGA VARC_ELNO VARC_NOEU VARI_ELNO VARI_NOEU FLHN_ELGA TEMP_ELGA ' // &
        'FLUX_ELGA FLUX_ELNO FLUX_NOEU GRAT_ELGA GRAT_ELNO GRAT_NOEU HYDR_ELGA HYDR_ELNO ' // &
        'HYDR_NOEU SOUR_ELGA ETHE_ELEM HHO_TEMP DIFF_ELGA DIFF_ELNO DIFF_NOEU HYGR_ELGA ' // &
        'HYGR_ELNO HYGR_NOEU PRAC_ELNO PRAC_NOEU PRME_ELNO INTE_ELNO INTE_NOEU FORC_NODA ' // &
        'REAC_NODA SIZ1_NOEU ERZ1_ELEM SIZ2_NOEU ERZ2_ELEM ERME_ELEM ERME_ELNO ERME_NOEU ' // &
        'QIRE_ELEM QIRE_ELNO QIRE_NOEU QIZ1_ELEM QIZ2_ELEM SING_ELEM SING_ELNO ERTH_ELEM ' // &
        'ERTH_ELNO ERTH_NOEU DURT_ELNO DURT_NOEU META_ELNO META_NOEU ACCE ACCE_ABSOLU DEPL ' // &
        'DEPL_ABSOLU HHO_DEPL TEMP VITE HHO_VITE CONT_NOEU CONT_ELEM VARI_ELGA VITE_ABSOLU ' // &
        'DEPL_ELGA SECH MATE_ELGA MATE_ELEM COMPORTEMENT COMPORTHER DEPL_VIBR DIVU EPSA_ELNO ' // &
        'EPSA_NOEU FERR_ELEM MARG_ELEM FSUR_2D FSUR_3D FVOL_2D FVOL_3D COEF_H T_EXT IRRA ' // &
        'MODE_FLAMB MODE_STAB NEUT PRES PRES_NOEU PTOT RESI_NOEU RESI_RELA_NOEU SISE_ELNO ' // &
        'VITE_VENT'

    !> The physical quantities of TYPE_CHAM (the fields layer's FIELD_QUANTITY_NAMES;
    !> test_catalog_fields checks that the two lists agree).
    character(len=*), parameter, public :: TYPE_CHAM_QUANTITIES = 'DEPL_R DEPL_F SIEF_R ' // &
        'EPSI_R TEMP_R TEMP_F NEUT_R NEUT_F GEOM_R ENER_R VARI_R HYDR_R ERRE_R SING_R ' // &
        'FER2_R FORC_R FORC_F PRES_R PRES_F'
    !> The locations of TYPE_CHAM (Code_Aster's C_TYPE_CHAM_INTO: <location>_<quantity>).
    character(len=*), parameter, public :: TYPE_CHAM_LOCATIONS = 'NOEU ELGA ELNO ELEM CART'

    public :: describe_fields, type_cham_names

contains

    !> Every TYPE_CHAM parasol makes: each location with each quantity.
    function type_cham_names() result(text)
        use deck_catalog, only: split_words
        use strings, only: string_t
        character(len=:), allocatable :: text
        type(string_t), allocatable :: locations(:), quantities(:)
        integer :: i, j
        call split_words(TYPE_CHAM_LOCATIONS, locations)
        call split_words(TYPE_CHAM_QUANTITIES, quantities)
        text = ''
        do i = 1, size(locations)
            do j = 1, size(quantities)
                text = text // ' ' // locations(i)%s // '_' // quantities(j)%s
            end do
        end do
    end function type_cham_names

    !> CREA_CHAMP (code_aster/Cata/Commands/crea_champ.py, U4.72.04): its blocks by
    !> OPERATION are flattened here (the catalog has no conditional blocks); what belongs to
    !> which operation is checked by the handler (post/crea_champ_command), located.
    subroutine describe_fields(c)
        use deck_catalog, only: catalog_t, MANY, RULE_UN_PARMI, RULE_EXCLUS, &
            RULE_AU_MOINS_UN, RULE_PRESENT_PRESENT
        use catalog_common, only: OUI_NON
        type(catalog_t), intent(inout) :: c
        call c%command('CREA_CHAMP', '@TYPE_CHAM', reentrant='f:CHAM_GD')
        call c%key('TYPE_CHAM', 'TXM', req=.true., into=type_cham_names())
        call c%key('OPERATION', 'TXM', req=.true., into='AFFE ASSE ASSE_DEPL EVAL EXTR ' // &
            'DISC NORMALE R2C C2R COMB')
        call c%key('NUME_DDL', 'nume_ddl_sdaster', noop=.true.)
        call c%key('CHAM_NO', 'cham_no_sdaster', noop=.true.)
        call c%rule(RULE_EXCLUS, 'NUME_DDL CHAM_NO')
        call c%key('PROL_ZERO', 'TXM', def='NON', into=OUI_NON)
        call c%key('OPTION', 'TXM', noop=.true.)
        call c%fact('AFFE_SP', noop=.true.)
        call c%key('CARA_ELEM', 'cara_elem', req=.true.)
        call c%end_fact()
        call c%key('MAILLAGE', 'maillage')
        call c%key('MODELE', 'modele')
        call c%rule(RULE_EXCLUS, 'MAILLAGE MODELE')
        call c%key('GROUP_MA', 'TXM', max=MANY)                 ! OPERATION='NORMALE'
        call c%fact('AFFE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%key('MAILLE', 'TXM', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT GROUP_MA GROUP_NO NOEUD MAILLE')
        call c%key('NOM_CMP', 'TXM', max=MANY, req=.true.)
        call c%key('VALE', 'R', max=MANY)
        call c%key('VALE_I', 'I', max=MANY)
        call c%key('VALE_F', 'FUNC', max=MANY)
        call c%rule(RULE_UN_PARMI, 'VALE VALE_I VALE_F')
        call c%end_fact()
        call c%fact('ASSE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT GROUP_MA GROUP_NO')
        call c%key('CHAM_GD', 'CHAM_GD', req=.true.)
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%key('NOM_CMP_RESU', 'TXM', max=MANY)
        call c%rule(RULE_PRESENT_PRESENT, 'NOM_CMP_RESU NOM_CMP')
        call c%key('CUMUL', 'TXM', def='NON', into=OUI_NON)
        call c%key('COEF_R', 'R', def='1.0')
        call c%end_fact()
        call c%fact('COMB', max=MANY)
        call c%key('CHAM_GD', 'cham_no_sdaster', req=.true.)
        call c%key('COEF_R', 'R', req=.true.)
        call c%end_fact()
        call c%key('CHAM_F', 'CHAM_GD')
        call c%key('CHAM_PARA', 'CHAM_GD', max=MANY)
        call c%key('CHAM_GD', 'CHAM_GD')
        call c%key('PARTIE', 'TXM', into='REEL IMAG MODULE PHASE')
        call c%key('RESULTAT', 'RESU')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%key('CHARGE', 'char_meca')
        call c%key('NOM_CHAM', 'TXM', into=NOM_CHAM_NAMES // ' GEOMETRIE ABSC_CURV')
        call c%key('TYPE_MAXI', 'TXM', into='MAXI MINI MAXI_ABS MINI_ABS NORM_TRAN')
        call c%key('TYPE_RESU', 'TXM', into='VALE INST VALE_ABS NUME_ORDRE')
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('LIST_INST', 'listr8')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%rule(RULE_EXCLUS, 'NUME_ORDRE INST TOUT_ORDRE LIST_INST')
        call c%key('INTERPOL', 'TXM', def='NON', into='NON LIN')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', noop=.true.)
        call describe_calc_champ(c)
        call describe_crea_resu(c)
        call describe_post_champ(c)
        call describe_modi_repere(c)
        call describe_lire_champ(c)
        call describe_proj_champ(c)
        call describe_calc_erreur(c)
    end subroutine describe_fields

    !> CALC_ERREUR (code_aster/Cata/Commands/calc_erreur.py, U4.81.04): the type of
    !> RESULTAT; OPTION takes Code_Aster's error options (the handler refuses those not built).
    subroutine describe_calc_erreur(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS
        type(catalog_t), intent(inout) :: c
        call c%command('CALC_ERREUR', '@RESULTAT', reentrant='f:RESULTAT')
        call c%key('RESULTAT', 'RESU', req=.true.)
        call c%key('MODELE', 'modele', noop=.true.)
        call c%key('CHAM_MATER', 'cham_mater', noop=.true.)
        call c%key('CARA_ELEM', 'cara_elem', noop=.true.)
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST LIST_INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT', 'TXM', def='OUI', into='OUI')
        call c%key('OPTION', 'TXM', req=.true., max=MANY, into='SIZ1_NOEU ERZ1_ELEM ' // &
            'SIZ2_NOEU ERZ2_ELEM ERME_ELEM ERME_ELNO ERME_NOEU QIRE_ELEM QIRE_ELNO ' // &
            'QIRE_NOEU QIZ1_ELEM QIZ2_ELEM SING_ELEM SING_ELNO ERTH_ELEM ERTH_ELNO ERTH_NOEU')
        call c%key('RESU_DUAL', 'RESU')
        call c%key('PREC_ERR', 'R', vmin=0.0_dp)
        call c%key('TYPE_ESTI', 'TXM', into='ERME_ELEM ERZ1_ELEM ERZ2_ELEM QIRE_ELEM ' // &
            'QIZ1_ELEM QIZ2_ELEM')
        call c%fact('EXCIT', max=MANY, noop=.true.)
        call c%key('CHARGE', 'char_meca|char_cine_meca', req=.true.)
        call c%key('FONC_MULT', 'FUNC')
        call c%end_fact()
        call c%fact('SOLVEUR', noop=.true.)
        call c%key('METHODE', 'TXM', into='LDLT MULT_FRONT MUMPS PETSC GCPC')
        call c%key('RENUM', 'TXM')
        call c%key('NPREC', 'I')
        call c%key('STOP_SINGULIER', 'TXM', into='OUI NON')
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2', noop=.true.)
        call c%key('TITRE', 'TXM', noop=.true.)
    end subroutine describe_calc_erreur

    !> PROJ_CHAMP (code_aster/Cata/Commands/proj_champ.py, U4.72.05): the type of RESULTAT or
    !> CHAM_GD, else (PROJECTION='NON') a corresp_2_mailla. The blocks of PROJECTION are
    !> flattened: METHODE takes every method (the handler refuses those not built; its
    !> default is AUTO, COLLOCATION with PROJECTION='NON').
    subroutine describe_proj_champ(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_AU_MOINS_UN
        type(catalog_t), intent(inout) :: c
        call c%command('PROJ_CHAMP', '@RESULTAT CHAM_GD corresp_2_mailla', &
            reentrant='f:RESULTAT')
        call c%key('PROJECTION', 'TXM', def='OUI', into='OUI NON')
        call c%key('MATR_PROJECTION', 'corresp_2_mailla')
        call c%key('METHODE', 'TXM', into='AUTO COLLOCATION NUAGE_DEG_0 NUAGE_DEG_1 ' // &
            'ECLA_PG SOUS_POINT COUPLAGE')
        call c%rule(RULE_EXCLUS, 'RESULTAT CHAM_GD')
        call c%rule(RULE_EXCLUS, 'MODELE_1 MAILLAGE_1')
        call c%rule(RULE_EXCLUS, 'MODELE_2 MAILLAGE_2')
        call c%key('RESULTAT', 'RESU')
        call c%key('CHAM_GD', 'CHAM_GD')
        call c%key('MODELE_1', 'modele')
        call c%key('MAILLAGE_1', 'maillage')
        call c%key('MODELE_2', 'modele')
        call c%key('MAILLAGE_2', 'maillage')
        call c%key('CHAM_NO_REFE', 'cham_no_sdaster')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%key('CAS_FIGURE', 'TXM', into='2D 3D 2.5D 1.5D')
        call c%key('DISTANCE_MAX', 'R', vmin=0.0_dp)
        call c%key('DISTANCE_ALARME', 'R', vmin=0.0_dp)
        call c%key('TRANSF_GEOM_1', 'FUNC', min=2, max=3)
        call c%key('TRANSF_GEOM_2', 'FUNC', min=2, max=3)
        call c%key('ALARME', 'TXM', def='OUI', into='OUI NON')
        call c%key('TYPE_CHAM', 'TXM', into='NOEU', noop=.true.)
        call c%key('PROL_VALE', 'R')
        call c%key('PROL_ZERO', 'TXM', into='OUI NON')
        call c%rule(RULE_EXCLUS, 'PROL_VALE PROL_ZERO')
        call c%key('NOM_PARA', 'TXM', max=MANY, noop=.true.)
        call c%key('TOUT_CHAM', 'TXM', into='OUI')
        call c%key('NOM_CHAM', 'TXM', max=MANY, into=NOM_CHAM_NAMES)
        call c%rule(RULE_EXCLUS, 'TOUT_CHAM NOM_CHAM')
        call c%key('NUME_DDL', 'nume_ddl_sdaster', noop=.true.)
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST LIST_INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%fact('VIS_A_VIS', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT_1 GROUP_MA_1 MAILLE_1 GROUP_NO_1 NOEUD_1')
        call c%rule(RULE_AU_MOINS_UN, 'TOUT_2 GROUP_MA_2 GROUP_NO_2 NOEUD_2')
        call c%key('TOUT_1', 'TXM', into='OUI')
        call c%key('GROUP_MA_1', 'TXM', max=MANY)
        call c%key('MAILLE_1', 'TXM', max=MANY)
        call c%key('GROUP_NO_1', 'TXM', max=MANY)
        call c%key('NOEUD_1', 'TXM', max=MANY)
        call c%key('TOUT_2', 'TXM', into='OUI')
        call c%key('GROUP_MA_2', 'TXM', max=MANY)
        call c%key('GROUP_NO_2', 'TXM', max=MANY)
        call c%key('NOEUD_2', 'TXM', max=MANY)
        call c%key('CAS_FIGURE', 'TXM', into='2D 3D 2.5D 1.5D 0D')
        call c%key('TRANSF_GEOM_1', 'FUNC', min=2, max=3)
        call c%key('TRANSF_GEOM_2', 'FUNC', min=2, max=3)
        call c%key('DISTANCE_0D', 'R', vmin=0.0_dp)
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2', noop=.true.)
    end subroutine describe_proj_champ

    !> LIRE_CHAMP (code_aster/Cata/Commands/lire_champ.py, U7.02.02): a field of a MED file,
    !> of the type of TYPE_CHAM.
    subroutine describe_lire_champ(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, &
            RULE_PRESENT_PRESENT
        type(catalog_t), intent(inout) :: c
        call c%command('LIRE_CHAMP', '@TYPE_CHAM')
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%key('FORMAT', 'TXM', def='MED', into='MED')
        call c%key('UNITE', 'I', def='81')
        call c%rule(RULE_UN_PARMI, 'NOM_CMP_IDEM NOM_CMP')
        call c%rule(RULE_PRESENT_PRESENT, 'NOM_CMP NOM_CMP_MED')
        call c%rule(RULE_EXCLUS, 'NUME_ORDRE INST')
        call c%rule(RULE_EXCLUS, 'NUME_PT INST')
        call c%key('NOM_MED', 'TXM', req=.true.)
        call c%key('NOM_CMP_IDEM', 'TXM', into='OUI')
        call c%key('NOM_CMP', 'TXM', max=MANY)
        call c%key('NOM_CMP_MED', 'TXM', max=MANY)
        call c%key('PROL_ZERO', 'TXM', def='NON', into='OUI NON')
        call c%key('NUME_PT', 'I', max=MANY)
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('NOM_MAIL_MED', 'TXM', noop=.true.)
        call c%key('TYPE_CHAM', 'TXM', req=.true., into=type_cham_names())
        call c%key('MODELE', 'modele')
        call c%key('INFO', 'I', def='1', into='1 2', noop=.true.)
    end subroutine describe_lire_champ

    !> MODI_REPERE (code_aster/Cata/Commands/modi_repere.py, U4.74.01): the type of the
    !> RESULTAT or CHAM_GD given; REPERE UTILISATEUR and CYLINDRIQUE (the others refused by
    !> the handler).
    subroutine describe_modi_repere(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_ENSEMBLE
        type(catalog_t), intent(inout) :: c
        call c%command('MODI_REPERE', '@RESULTAT CHAM_GD', reentrant='f:RESULTAT')
        call c%rule(RULE_UN_PARMI, 'CHAM_GD RESULTAT')
        call c%key('CHAM_GD', 'CHAM_GD')
        call c%key('RESULTAT', 'RESU')
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST LIST_INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%fact('MODI_CHAM', max=MANY)
        call c%key('TYPE_CHAM', 'TXM', req=.true., &
            into='VECT_2D VECT_3D TENS_2D TENS_3D COQUE_GENE 1D_GENE')
        call c%key('NOM_CHAM', 'TXM', req=.true., into=NOM_CHAM_NAMES)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%key('NOM_CHAM_RESU', 'TXM', into='EGRU_ELNO', noop=.true.)
        call c%end_fact()
        call c%key('REPERE', 'TXM', req=.true., into='UTILISATEUR CYLINDRIQUE COQUE ' // &
            'GLOBAL_UTIL COQUE_INTR_UTIL COQUE_UTIL_INTR COQUE_UTIL_CYL')
        call c%fact('AFFE', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA GROUP_NO')
        call c%rule(RULE_EXCLUS, 'ANGL_NAUT VECT_X ORIGINE')
        call c%rule(RULE_ENSEMBLE, 'VECT_X VECT_Y')
        call c%key('ANGL_NAUT', 'R', max=3)
        call c%key('VECT_X', 'R', min=3, max=3)
        call c%key('VECT_Y', 'R', min=3, max=3)
        call c%key('ORIGINE', 'R', min=2, max=3)
        call c%key('AXE_Z', 'R', min=3, max=3)
        call c%key('ANGL_REP', 'R', min=2, max=2, noop=.true.)
        call c%key('VECTEUR', 'R', min=3, max=3, noop=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2', noop=.true.)
    end subroutine describe_modi_repere

    !> POST_CHAMP (code_aster/Cata/Commands/post_champ.py, U4.81.05): the result's type.
    subroutine describe_post_champ(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI
        type(catalog_t), intent(inout) :: c
        character(len=*), parameter :: EXTR = 'EPEQ_ELGA EPEQ_ELNO EPSI_ELGA EPSI_ELNO ' // &
            'SIEF_ELGA SIEF_ELNO SIEQ_ELGA SIEQ_ELNO SIGM_ELGA SIGM_ELNO VARC_ELGA VARC_ELNO ' // &
            'VARI_ELGA VARI_ELNO EPVC_ELGA EPVC_ELNO EPME_ELGA EPME_ELNO EPSP_ELGA EPSP_ELNO'
        call c%command('POST_CHAMP', '@RESULTAT')
        call c%key('RESULTAT', 'RESU', req=.true.)
        call c%rule(RULE_UN_PARMI, 'EXTR_COQUE EXTR_TUYAU EXTR_PMF MIN_MAX_SP COQU_EXCENT')
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('NUME_MODE', 'I', max=MANY, noop=.true.)
        call c%key('NOEUD_CMP', 'TXM', max=MANY, noop=.true.)
        call c%key('NOM_CAS', 'TXM', max=MANY, noop=.true.)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%key('FREQ', 'R', max=MANY, noop=.true.)
        call c%key('LIST_FREQ', 'listr8', noop=.true.)
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST FREQ NUME_MODE NOEUD_CMP ' // &
            'LIST_INST LIST_FREQ NOM_CAS')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%fact('EXTR_COQUE')
        call c%key('NOM_CHAM', 'TXM', req=.true., max=MANY, into=EXTR)
        call c%key('NUME_COUCHE', 'I', req=.true., vmin=1.0_dp)
        call c%key('NIVE_COUCHE', 'TXM', req=.true., into='SUP INF MOY')
        call c%end_fact()
        call c%fact('EXTR_TUYAU')
        call c%key('NOM_CHAM', 'TXM', req=.true., max=MANY, into=EXTR)
        call c%key('NUME_COUCHE', 'I', req=.true., vmin=1.0_dp)
        call c%key('NIVE_COUCHE', 'TXM', req=.true., into='SUP INF MOY')
        call c%key('ANGLE', 'I', req=.true., vmin=0.0_dp, vmax=360.0_dp)
        call c%end_fact()
        call c%fact('EXTR_PMF')
        call c%key('NOM_CHAM', 'TXM', req=.true., max=MANY, into=EXTR)
        call c%key('NUME_FIBRE', 'I', req=.true., vmin=1.0_dp)
        call c%end_fact()
        call c%fact('MIN_MAX_SP', max=MANY)
        call c%key('NOM_CHAM', 'TXM', req=.true., into=EXTR)
        call c%key('NOM_CMP', 'TXM')
        call c%key('NOM_VARI', 'TXM')
        call c%rule(RULE_UN_PARMI, 'NOM_CMP NOM_VARI')
        call c%key('TYPE_MAXI', 'TXM', req=.true., into='MAXI MINI MAXI_ABS MINI_ABS')
        call c%key('NUME_CHAM_RESU', 'I', req=.true., vmin=1.0_dp, vmax=20.0_dp)
        call c%end_fact()
        call c%fact('COQU_EXCENT', max=2)
        call c%key('NOM_CHAM', 'TXM', req=.true., into='EFGE_ELNO EFGE_ELGA')
        call c%key('MODI_PLAN', 'TXM', req=.true., into='OUI')
        call c%end_fact()
    end subroutine describe_post_champ

    !> CREA_RESU (code_aster/Cata/Commands/crea_resu.py, U4.44.12): its result type is
    !> TYPE_RESU's ('@TYPE_RESU'); the AFFE block's keywords; the other operations are
    !> refused by the handler as not built.
    subroutine describe_crea_resu(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI
        type(catalog_t), intent(inout) :: c
        call c%command('CREA_RESU', '@TYPE_RESU', reentrant='f:RESULTAT')
        call c%key('OPERATION', 'TXM', req=.true., into='AFFE ASSE PERM_CHAM PROL_RTZ ' // &
            'PREP_VARC KUCV CONV_CHAR CONV_RESU')
        call c%key('TYPE_RESU', 'TXM', req=.true., into='MODE_MECA MODE_MECA_C MULT_ELAS ' // &
            'EVOL_ELAS EVOL_NOLI DYNA_HARMO DYNA_TRANS FOURIER_ELAS FOURIER_THER EVOL_THER ' // &
            'EVOL_VARC EVOL_CHAR EVOL_SECH')
        call c%key('RESULTAT', 'RESU')
        call c%fact('AFFE', max=MANY)
        call c%key('CHAM_GD', 'CHAM_GD', req=.true.)
        call c%key('NOM_CHAM', 'TXM', req=.true., into=NOM_CHAM_NAMES // ' FLUN')
        call c%key('MODELE', 'modele')
        call c%key('CHAM_MATER', 'cham_mater')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%key('CHARGE', 'char_meca', max=MANY, noop=.true.)
        call c%key('NOM_CAS', 'TXM')
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%rule(RULE_EXCLUS, 'INST LIST_INST NOM_CAS')
        call c%key('NUME_INIT', 'I', vmin=1.0_dp)
        call c%key('NUME_FIN', 'I', vmin=1.0_dp)
        call c%key('PRECISION', 'R', def='0.0', vmin=0.0_dp)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%end_fact()
        call c%fact('PREP_VARC')
        call c%key('CHAM_GD', 'CHAM_GD')
        call c%key('EVOL_THER', 'evol_ther')
        call c%rule(RULE_UN_PARMI, 'CHAM_GD EVOL_THER')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('CARA_ELEM', 'cara_elem', req=.true.)
        call c%bloc(exists='EVOL_THER')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%key('LIST_INST', 'listr8')
        call c%key('INST', 'R', max=MANY)
        call c%rule(RULE_EXCLUS, 'LIST_INST INST')
        call c%bloc(exists='INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%end_bloc()
        call c%bloc(exists='LIST_INST')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%end_bloc()
        call c%end_bloc()
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', noop=.true.)
    end subroutine describe_crea_resu

    !> CALC_CHAMP (code_aster/Cata/Commands/calc_champ.py, U4.81.04): the result's own type
    !> ('@RESULTAT'); the options of each keyword are Code_Aster's for linear and non-linear
    !> results (C_NOM_CHAM_INTO by phenomenon); which are built, and for which kind of
    !> result, the handler says (post/calc_champ_command).
    subroutine describe_calc_champ(c)
        use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_AU_MOINS_UN
        type(catalog_t), intent(inout) :: c
        call c%command('CALC_CHAMP', '@RESULTAT', reentrant='f:RESULTAT')
        call c%key('MODELE', 'modele')
        call c%key('CHAM_MATER', 'cham_mater')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%key('RESULTAT', 'RESU', req=.true.)
        call c%key('TOUT_ORDRE', 'TXM', into='OUI')
        call c%key('NUME_ORDRE', 'I', max=MANY)
        call c%key('INST', 'R', max=MANY)
        call c%key('LIST_INST', 'listr8')
        call c%key('NUME_MODE', 'I', max=MANY, noop=.true.)
        call c%key('FREQ', 'R', max=MANY, noop=.true.)
        call c%key('LIST_FREQ', 'listr8', noop=.true.)
        call c%key('NOM_CAS', 'TXM', noop=.true.)
        call c%rule(RULE_EXCLUS, 'TOUT_ORDRE NUME_ORDRE INST LIST_INST NUME_MODE FREQ ' // &
            'LIST_FREQ NOM_CAS')
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%key('CONTRAINTE', 'TXM', max=MANY, into='EFGE_ELGA EFGE_ELNO EGRU_ELNO ' // &
            'EFGE_NOEU SIEF_ELGA SIEF_ELNO SIMY_ELGA SIEF_NOEU SIGM_ELGA SIGM_ELNO SIGM_NOEU ' // &
            'SIPM_ELNO SIPO_ELNO SIPO_NOEU SIRO_ELEM STRX_ELGA')
        call c%key('DEFORMATION', 'TXM', max=MANY, into='DEGE_ELGA DEGE_ELNO DEGE_NOEU ' // &
            'EPFD_ELGA EPFD_ELNO EPFD_NOEU EPFP_ELGA EPFP_ELNO EPFP_NOEU EPME_ELGA EPME_ELNO ' // &
            'EPME_NOEU EPMG_ELGA EPMG_ELNO EPMG_NOEU EPSG_ELGA EPSG_ELNO EPSG_NOEU EPSI_ELGA ' // &
            'EPSI_ELNO EPSI_NOEU EPSP_ELGA EPSP_ELNO EPSP_NOEU EPVC_ELGA EPVC_ELNO EPVC_NOEU ' // &
            'EPSL_ELGA EPSL_ELNO EPSL_NOEU')
        call c%key('ENERGIE', 'TXM', max=MANY, into='DISS_ELEM DISS_ELGA DISS_ELNO ' // &
            'DISS_NOEU ECIN_ELEM ENEL_ELEM ENEL_ELGA ENEL_ELNO ENEL_NOEU ENTR_ELEM EPOT_ELEM ' // &
            'ETOT_ELEM ETOT_ELGA ETOT_ELNO ETOT_NOEU')
        call c%key('CRITERES', 'TXM', max=MANY, into='DERA_ELGA DERA_ELNO DERA_NOEU ' // &
            'ENDO_ELGA ENDO_ELNO ENDO_NOEU EPEQ_ELGA EPEQ_ELNO EPEQ_NOEU EPGQ_ELGA EPGQ_ELNO ' // &
            'EPGQ_NOEU EPMQ_ELGA EPMQ_ELNO EPMQ_NOEU INDL_ELGA PDIL_ELGA SIEQ_ELGA SIEQ_ELNO ' // &
            'SIEQ_NOEU')
        call c%key('VARI_INTERNE', 'TXM', max=MANY, into='VARC_ELGA VARC_ELNO VARC_NOEU ' // &
            'VARI_ELNO VARI_NOEU')
        call c%key('PROPRIETES', 'TXM', max=MANY, into='MATE_ELGA MATE_ELEM')
        call c%key('HYDRAULIQUE', 'TXM', max=MANY, into='FLHN_ELGA')
        call c%key('FORCE', 'TXM', max=MANY, into='FORC_NODA REAC_NODA')
        call c%key('SOUS_POINT', 'TXM', max=MANY, into='DEPL_ELGA TEMP_ELGA')
        call c%fact('EXCIT', max=MANY)
        call c%key('CHARGE', 'char_meca|char_cine_meca', req=.true.)
        call c%key('FONC_MULT', 'FUNC')
        call c%key('COEF_MULT', 'R')
        call c%rule(RULE_EXCLUS, 'FONC_MULT COEF_MULT')
        call c%key('TYPE_CHARGE', 'TXM', def='FIXE_CSTE', into='FIXE_CSTE FIXE_PILO SUIV DIDI')
        call c%end_fact()
        call c%fact('CHAM_UTIL', max=MANY)
        call c%key('NOM_CHAM', 'TXM', req=.true.)
        call c%key('FORMULE', 'formule', max=MANY)
        call c%key('CRITERE', 'TXM', into='TRACE VMIS INVA_2')
        call c%key('NORME', 'TXM', into='L2 FROBENIUS')
        call c%key('NUME_CHAM_RESU', 'I', req=.true., vmin=1.0_dp, vmax=20.0_dp)
        call c%end_fact()
        call c%rule(RULE_AU_MOINS_UN, 'SOUS_POINT CONTRAINTE DEFORMATION ENERGIE CRITERES ' // &
            'VARI_INTERNE PROPRIETES HYDRAULIQUE FORCE CHAM_UTIL')
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', noop=.true.)
    end subroutine describe_calc_champ

end module catalog_fields
