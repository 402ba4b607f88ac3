!> The catalog of DEFI_LIST_INST (Code_Aster U4.34.03): a list of instants for
!> STAT_NON_LINE and what to do when a step fails (ECHEC).
!> Code_Aster describes the keywords of an event or an action in conditional blocks (their
!> condition: EVENEMENT, ACTION, SUBD_METHODE); parasol's catalog has no blocks, so those
!> keywords are the union of the blocks, without the defaults that depend on the condition:
!> time_stepping applies Code_Aster's (ACTION by EVENEMENT, SUBD_PAS = 4, SUBD_NIVEAU = 3,
!> SUBD_PAS_MINI = 0, PCENT_ITER_PLUS = 50, COEF_MAXI = 1e12) where they apply.
!> Part of THE command catalog (deck_catalog_data gathers the parts).
module catalog_list_inst
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_UN_PARMI, RULE_PRESENT_PRESENT, RULE_EXCLUS
    use number_limits, only: MAX_INSTANT
    implicit none
    private
    public :: describe_list_inst

    !> SUBD_PAS at most (parasol's bound: Code_Aster has none; the steps a cut makes are
    !> allocated and run, contact_newton also bounds their total).
    real(dp), parameter :: MAX_SUBD_PAS = 1.0e6_dp

contains

    subroutine describe_list_inst(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEFI_LIST_INST', 'list_inst')
        call c%key('MODELE', 'modele')
        call c%key('METHODE', 'TXM', def='MANUEL', into='MANUEL AUTO')
        ! DEFI_LIST (blocks b_manuel and b_auto, both statut 'o')
        call c%fact('DEFI_LIST', req=.true.)
        call c%key('VALE', 'R', max=MANY, vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('LIST_INST', 'listr8')
        call c%key('RESULTAT', 'RESU')
        call c%key('SUBD_PAS', 'I', vmin=1.0_dp, vmax=MAX_SUBD_PAS)
        call c%key('PAS_MINI', 'R', vmin=1.0e-12_dp)
        call c%key('PAS_MAXI', 'R')
        call c%key('NB_PAS_MAXI', 'I', vmax=1.0e6_dp)
        call c%rule(RULE_UN_PARMI, 'LIST_INST VALE RESULTAT')
        call c%rule(RULE_PRESENT_PRESENT, 'RESULTAT SUBD_PAS')
        call c%end_fact()
        call describe_echec(c)
        call describe_adaptation(c)
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_list_inst

    !> ECHEC (statut 'd': without it, one occurrence with its defaults).
    subroutine describe_echec(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('ECHEC', max=MANY)
        call c%key('EVENEMENT', 'TXM', def='ERREUR', into='ERREUR DELTA_GRANDEUR ' // &
                   'RESI_MAXI INTERPENETRATION DIVE_RESI INSTABILITE')
        call c%key('ACTION', 'TXM', into='ARRET DECOUPE ITER_SUPPL ADAPT_COEF_PENA CONTINUE')
        call c%key('SUBD_METHODE', 'TXM', into='MANUEL AUTO')
        call c%key('SUBD_PAS', 'I', vmin=2.0_dp, vmax=MAX_SUBD_PAS)
        call c%key('SUBD_NIVEAU', 'I', vmin=0.0_dp)
        call c%key('SUBD_PAS_MINI', 'R', vmin=0.0_dp)
        call c%key('PCENT_ITER_PLUS', 'I', vmin=20.0_dp)
        call c%key('COEF_MAXI', 'R', vmin=1.0_dp)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'GROUP_MA GROUP_NO')
        call c%key('VALE_REF', 'R')
        call c%key('NOM_CHAM', 'TXM', into='DEPL VARI_ELGA SIEF_ELGA')
        call c%key('NOM_CMP', 'TXM')
        call c%key('PENE_MAXI', 'R')
        call c%key('RESI_GLOB_MAXI', 'R')
        call c%end_fact()
    end subroutine describe_echec

    !> ADAPTATION (block b_adap, METHODE = 'AUTO').
    subroutine describe_adaptation(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('ADAPTATION', max=MANY)
        call c%key('EVENEMENT', 'TXM', def='SEUIL', into='SEUIL TOUT_INST AUCUN')
        call c%key('NB_INCR_SEUIL', 'I')
        call c%key('NOM_PARA', 'TXM', into='NB_ITER_NEWTON')
        call c%key('CRIT_COMP', 'TXM', into='LT GT LE GE')
        call c%key('VALE_I', 'I')
        call c%key('MODE_CALCUL_TPLUS', 'TXM', def='FIXE', &
                   into='FIXE DELTA_GRANDEUR ITER_NEWTON IMPLEX')
        call c%key('PCENT_AUGM', 'R', vmin=-100.0_dp)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'GROUP_MA GROUP_NO')
        call c%key('VALE_REF', 'R')
        call c%key('NOM_CHAM', 'TXM', into='DEPL VARI_ELGA SIEF_ELGA')
        call c%key('NOM_CMP', 'TXM')
        call c%key('NB_ITER_NEWTON_REF', 'I')
        call c%end_fact()
    end subroutine describe_adaptation

end module catalog_list_inst
