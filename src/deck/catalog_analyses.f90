!> The catalog of the analyses: MECA_STATIQUE, STAT_NON_LINE and their SOLVEUR.
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_analyses
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_AU_MOINS_UN
    use number_limits, only: MAX_INSTANT
    use catalog_common, only: OUI_NON
    implicit none
    private
    public :: describe_analyses

contains

    subroutine describe_analyses(c)
        type(catalog_t), intent(inout) :: c
        call c%command('MECA_STATIQUE', 'evol_elas', reentrant='f:RESULTAT')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('CHAM_MATER', 'cham_mater')
        call c%key('CARA_ELEM', 'cara_elem')
        call c%fact('EXCIT', max=MANY, req=.true.)
        call c%key('CHARGE', 'char_meca|char_cine_meca', req=.true.)
        call c%key('FONC_MULT', 'FUNC')
        call c%end_fact()
        call c%key('LIST_INST', 'listr8')
        call c%key('INST', 'R', max=MANY, vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%rule(RULE_EXCLUS, 'LIST_INST INST')
        call describe_solver(c)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('OPTION', 'TXM', noop=.true.)
        call c%key('TITRE', 'TXM', max=MANY, noop=.true.)

        ! reentrant 'f' (Code_Aster: 'f:ETAT_INIT/EVOL_NOLI'): the reused result must be the
        ! ETAT_INIT one, checked by the handler (run_stat_non_line), the new instants appended
        call c%command('STAT_NON_LINE', 'evol_noli', reentrant='f')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('CHAM_MATER', 'cham_mater', req=.true.)
        call c%key('CARA_ELEM', 'cara_elem')
        call c%fact('EXCIT', max=MANY, req=.true.)
        call c%key('CHARGE', 'char_meca|char_cine_meca', req=.true.)
        call c%key('FONC_MULT', 'FUNC')
        ! Code_Aster's stat_non_line.py: FIXE_CSTE (default), FIXE_PILO, SUIV, SUIV_PILO,
        ! DIDI; the handler builds FIXE_CSTE and SUIV (follower PRES_REP on plane edges,
        ! analysis_excitation) and refuses the others by name
        call c%key('TYPE_CHARGE', 'TXM', def='FIXE_CSTE', &
                   into='FIXE_CSTE FIXE_PILO SUIV SUIV_PILO DIDI')
        call c%end_fact()
        ! Code_Aster's ETAT_INIT (stat_non_line.py): a state of an EVOL_NOLI (NUME_ORDRE or
        ! INST, default its last) or fields DEPL, SIGM, VARI (refused by the handler: parasol
        ! has no field concept to start from yet)
        call c%fact('ETAT_INIT')
        call c%key('EVOL_NOLI', 'evol_noli')
        call c%key('DEPL', 'cham_no_sdaster')
        call c%key('SIGM', 'cham_no_sdaster')
        call c%key('VARI', 'cham_no_sdaster')
        call c%key('NUME_ORDRE', 'I', vmin=0.0_dp)
        call c%key('INST', 'R', vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('CRITERE', 'TXM', def='RELATIF', into='RELATIF ABSOLU')
        call c%key('PRECISION', 'R', def='1.0E-6', vmin=0.0_dp)
        call c%rule(RULE_EXCLUS, 'NUME_ORDRE INST')
        call c%rule(RULE_EXCLUS, 'EVOL_NOLI DEPL')
        call c%rule(RULE_EXCLUS, 'EVOL_NOLI SIGM')
        call c%rule(RULE_EXCLUS, 'EVOL_NOLI VARI')
        call c%rule(RULE_AU_MOINS_UN, 'EVOL_NOLI DEPL SIGM VARI')
        call c%end_fact()
        call c%fact('COMPORTEMENT', max=MANY)   ! statut 'd': absent = ELAS, PETIT on every cell
        call c%key('RELATION', 'TXM', def='ELAS', into='ELAS DIS_CHOC DIS_CONTACT')
        call c%key('DEFORMATION', 'TXM', def='PETIT', into='PETIT')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%end_fact()
        call c%fact('INCREMENT', req=.true.)
        call c%key('LIST_INST', 'listr8|list_inst', req=.true.)    ! DEFI_LIST_REEL, DEFI_LIST_INST
        call c%key('INST_INIT', 'R', vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('INST_FIN', 'R', vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('NUME_INST_INIT', 'I', vmin=0.0_dp)
        call c%key('NUME_INST_FIN', 'I', vmin=0.0_dp)
        call c%rule(RULE_EXCLUS, 'INST_INIT NUME_INST_INIT')
        call c%rule(RULE_EXCLUS, 'INST_FIN NUME_INST_FIN')
        call c%end_fact()
        call c%fact('NEWTON')
        call c%key('PREDICTION', 'TXM', into='TANGENTE ELASTIQUE')
        call c%key('MATRICE', 'TXM', def='TANGENTE', into='TANGENTE ELASTIQUE')
        call c%key('REAC_INCR', 'I', def='1', vmin=0.0_dp)     ! Code_Aster default, val_min
        call c%key('REAC_ITER', 'I', def='0', vmin=0.0_dp)     ! Code_Aster default, val_min
        ! Code_Aster symmetrises the tangent with 'OUI'; parasol's tangent is symmetric
        ! either way (it leaves out the non-symmetric follower-pressure stiffness:
        ! doc/analysis.md "Follower loads"), so both values mean the same here
        call c%key('MATR_RIGI_SYME', 'TXM', def='NON', into=OUI_NON, noop=.true.)
        call c%end_fact()
        ! Code_Aster's C_RECH_LINEAIRE (c_rech_lineaire.py): residual_line_search
        call c%fact('RECH_LINEAIRE')
        call c%key('METHODE', 'TXM', def='CORDE', into='CORDE MIXTE PILOTAGE')
        call c%key('RESI_LINE_RELA', 'R', def='1.0E-1', vmin=0.0_dp)
        call c%key('ITER_LINE_MAXI', 'I', def='3', vmin=0.0_dp, vmax=999.0_dp)
        call c%key('RHO_MIN', 'R', def='1.0E-2', vmin=0.0_dp)
        call c%key('RHO_MAX', 'R', def='1.0E1', vmin=0.0_dp)
        call c%key('RHO_EXCL', 'R', def='0.9E-2', vmin=0.0_dp)
        call c%end_fact()
        call c%fact('CONVERGENCE')
        call c%key('RESI_GLOB_RELA', 'R', vmin=0.0_dp)
        call c%key('RESI_GLOB_MAXI', 'R', vmin=0.0_dp)
        call c%key('ITER_GLOB_MAXI', 'I', def='10', vmin=0.0_dp)   ! Code_Aster default
        call c%key('ARRET', 'TXM', def='OUI', into=OUI_NON)
        call c%end_fact()
        call describe_solver(c)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', max=MANY, noop=.true.)
        call c%fact('ARCHIVAGE', noop=.true.)
        call c%key('LIST_INST', 'listr8', noop=.true.)
        call c%key('PAS_ARCH', 'I', noop=.true.)
        call c%end_fact()
    end subroutine describe_analyses

    !> SOLVEUR factor keyword of the analyses (defaults as Code_Aster's, c_solveur.py:
    !> METHODE='MUMPS', NPREC=8, STOP_SINGULIER='OUI'; RENUM's default depends on the method).
    !> GCPC and PETSC (krylov_solver): their keywords in their blocks, with Code_Aster's
    !> defaults; the preconditioners and algorithms parasol does not build are accepted here
    !> and refused by the analysis at the keyword (read_solver), never replaced.
    subroutine describe_solver(c)
        type(catalog_t), intent(inout) :: c
        character(len=*), parameter :: PETSC_PRE_COND = 'LDLT_INC LDLT_SP LDLT_DP JACOBI ' // &
            'SOR ML BOOMER GAMG BLOC_LAGR FIELDSPLIT UTILISATEUR HPDDM SANS'
        call c%fact('SOLVEUR')
        call c%key('METHODE', 'TXM', def='MUMPS', into='LDLT MULT_FRONT MUMPS GCPC PETSC')
        call c%key('RENUM', 'TXM', into='RCMK METIS SANS AMD MD AMF PORD SCOTCH QAMD AUTO')
        call c%key('NPREC', 'I', def='8')
        call c%key('STOP_SINGULIER', 'TXM', def='OUI', into=OUI_NON)
        call c%key('ELIM_LAGR', 'TXM', noop=.true.)
        call c%key('PCENT_PIVOT', 'I', noop=.true.)
        call c%key('GESTION_MEMOIRE', 'TXM', noop=.true.)
        call c%key('RESI_RELA', 'R')          ! GCPC, PETSC: 1e-6; MUMPS: its own check
        call c%key('POSTTRAITEMENTS', 'TXM', noop=.true.)
        call c%key('TYPE_RESOL', 'TXM', noop=.true.)
        call c%key('ACCELERATION', 'TXM', into='AUTO FR FR+ FR++ LR LR+ LR++')  ! MUMPS
        call c%key('LOW_RANK_SEUIL', 'R', noop=.true.)
        call c%key('MATR_DISTRIBUEE', 'TXM', noop=.true.)
        call c%key('PRETRAITEMENTS', 'TXM', noop=.true.)
        call c%key('FILTRAGE_MATRICE', 'R', noop=.true.)
        call c%key('MIXER_PRECISION', 'TXM', noop=.true.)
        call c%bloc(key='METHODE', equals='GCPC')
        call c%key('PRE_COND', 'TXM', def='LDLT_INC', into='LDLT_INC LDLT_SP LDLT_DP')
        call c%key('NMAX_ITER', 'I', def='0', vmin=0.0_dp)
        call c%key('NIVE_REMPLISSAGE', 'I', def='0', vmin=0.0_dp)
        call c%key('REAC_PRECOND', 'I', noop=.true.)
        call c%end_bloc()
        call c%bloc(key='METHODE', equals='PETSC')
        call c%key('ALGORITHME', 'TXM', def='FGMRES', into='CG CR GMRES GCR FGMRES GMRES_LMP')
        call c%key('PRE_COND', 'TXM', def='LDLT_SP', into=PETSC_PRE_COND)
        call c%key('NMAX_ITER', 'I', def='0', vmin=0.0_dp)
        call c%key('NIVE_REMPLISSAGE', 'I', def='0', vmin=0.0_dp)
        call c%key('REMPLISSAGE', 'R', noop=.true.)
        call c%key('REAC_PRECOND', 'I', noop=.true.)
        call c%key('OPTION_PETSC', 'TXM')
        call c%end_bloc()
        call c%end_fact()
    end subroutine describe_solver

end module catalog_analyses
