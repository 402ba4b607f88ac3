!> THE command catalog of parasol: every command of doc/deck-language.md with its keywords,
!> described once, as data (types, cardinality, defaults, allowed values, rules). Validation,
!> defaults and the documentation table all come from here. Defaults mirror Code_Aster's
!> (U4 documentation of each command); keywords marked noop are accepted so real decks run
!> unchanged, and have no effect in parasol.
module deck_catalog_data
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN
    use number_limits, only: MAX_LENGTH, MIN_LENGTH, MAX_MODULUS, MIN_MODULUS, MAX_INSTANT
    implicit none
    private
    public :: build_catalog

    character(len=*), parameter :: OUI_NON = 'OUI NON'
    !> Ranges (vmin, vmax) are Code_Aster's val_min/val_max where it has one (E >= 0,
    !> -1 <= NU <= 0.5, REAC_ITER >= 0 ...) and parasol's bounds of number_limits where the
    !> products formed from a value must stay finite (lengths, moduli, instants): issue 13.
    real(dp), parameter :: ANGLE_MAX = 1.0e30_dp          !< degrees, or a direction vector
    real(dp), parameter :: RATIO_MAX = 1.0e10_dp          !< COEF_RIGI_DRZ
    real(dp), parameter :: WEIGHT_MAX = 1.0e30_dp         !< RIGI_PARASOL COEF_GROUP
    !> NOM_CMP of TEST_RESU and IMPR_RESU: DEPL, FORC_NODA, REAC_NODA components; SIEF_ELGA
    !> of the discrete springs (N VY VZ); VARI_ELGA of DIS_CHOC (V1 .. V10).
    character(len=*), parameter :: RESULT_COMPONENTS = 'DX DY DZ DRX DRY DRZ N VY VZ ' // &
        'V1 V2 V3 V4 V5 V6 V7 V8 V9 V10'

contains

    !> Fills `cat` with every command.
    subroutine build_catalog(cat)
        type(catalog_t), intent(out) :: cat
        call describe_session(cat)
        call describe_mesh_and_model(cat)
        call describe_cara_elem(cat)
        call describe_functions(cat)
        call describe_loads(cat)
        call describe_analyses(cat)
        call describe_outputs(cat)
    end subroutine build_catalog

    subroutine describe_session(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEBUT', '')
        call describe_session_bookkeeping(c)

        ! POURSUITE (U4.11.03): continues the session of the previous command file; its
        ! keywords steer Code_Aster's database and messages, as DEBUT's do.
        call c%command('POURSUITE', '')
        call describe_session_bookkeeping(c)
        call c%key('FORMAT_HDF', 'TXM', into=OUI_NON, noop=.true.)

        call c%command('FIN', '')
        call c%key('FORMAT_HDF', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('RETASSAGE', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('INFO_RESU', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('PROC0', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('UNITE', 'I', noop=.true.)
    end subroutine describe_session

    !> The bookkeeping keywords DEBUT and POURSUITE share (U4.11.01, U4.11.03): accepted,
    !> no effect in parasol.
    subroutine describe_session_bookkeeping(c)
        type(catalog_t), intent(inout) :: c
        call c%key('CODE', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('DEBUG', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('PAR_LOT', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('IMPR_MACRO', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('LANG', 'TXM', noop=.true.)
        call c%key('ERREUR', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('MEMOIRE', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('RESERVE_CPU', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('IGNORE_ALARM', 'TXM', max=MANY, noop=.true.)
        call c%key('INFO', 'I', into='1 2', noop=.true.)
    end subroutine describe_session_bookkeeping

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

        call c%command('DEFI_MATERIAU', 'mater')
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

    subroutine describe_cara_elem(c)
        type(catalog_t), intent(inout) :: c
        character(len=*), parameter :: K_CARA = 'K_T_D_N K_T_D_L K_TR_D_N K_TR_D_L'
        call c%command('AFFE_CARA_ELEM', 'cara_elem')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%fact('COQUE', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('EPAIS', 'R', req=.true., vmax=MAX_LENGTH, vtiny=MIN_LENGTH)  ! > 0: handler
        call c%key('COQUE_NCOU', 'I', noop=.true.)
        call c%key('COEF_RIGI_DRZ', 'R', def='1.0E-5', &  ! Code_Aster default
                   vmin=-RATIO_MAX, vmax=RATIO_MAX)
        call c%key('ANGL_REP', 'R', min=2, max=2, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('VECTEUR', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('EXCENTREMENT', 'R', noop=.true.)
        call c%key('INER_ROTA', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('MODI_METRIQUE', 'TXM', into=OUI_NON, noop=.true.)
        call c%rule(RULE_EXCLUS, 'ANGL_REP VECTEUR')
        call c%end_fact()
        call c%fact('DISCRET', max=MANY)
        call describe_discrete(c, K_CARA)
        call c%end_fact()
        call c%fact('DISCRET_2D', max=MANY)
        call describe_discrete(c, K_CARA)
        call c%end_fact()
        call c%fact('ORIENTATION', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('CARA', 'TXM', req=.true., into='ANGL_VRIL VECT_Y ANGL_NAUT')
        call c%key('VALE', 'R', max=3, req=.true., vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%end_fact()
        call c%fact('RIGI_PARASOL', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('GROUP_MA_SEG2', 'TXM', max=MANY)
        call c%key('GROUP_MA_POI1', 'TXM', max=MANY)
        call c%key('COEF_GROUP', 'R', max=MANY, vmin=-WEIGHT_MAX, vmax=WEIGHT_MAX, &
                   vtiny=1.0_dp / WEIGHT_MAX)
        call c%key('FONC_GROUP', 'FUNC', max=MANY)
        call c%key('CARA', 'TXM', max=2, req=.true., into=K_CARA)
        call c%key('VALE', 'R', max=MANY, req=.true., vmin=-MAX_MODULUS, vmax=MAX_MODULUS, &
                   vtiny=MIN_MODULUS)
        call c%key('REPERE', 'TXM', def='GLOBAL', into='GLOBAL')
        call c%key('GROUP_NO_CENTRE', 'TXM')
        call c%key('NOEUD_CENTRE', 'TXM')
        call c%key('COOR_CENTRE', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%rule(RULE_UN_PARMI, 'GROUP_MA_SEG2 GROUP_MA_POI1')
        call c%rule(RULE_UN_PARMI, 'COEF_GROUP FONC_GROUP')
        call c%rule(RULE_EXCLUS, 'GROUP_NO_CENTRE NOEUD_CENTRE COOR_CENTRE')
        call c%end_fact()
        call c%rule(RULE_AU_MOINS_UN, 'COQUE DISCRET DISCRET_2D ORIENTATION RIGI_PARASOL')
    end subroutine describe_cara_elem

    subroutine describe_discrete(c, cara)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: cara
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('CARA', 'TXM', req=.true., into=cara)
        call c%key('VALE', 'R', max=MANY, req=.true., vmin=-MAX_MODULUS, vmax=MAX_MODULUS, &
                   vtiny=MIN_MODULUS)
        call c%key('REPERE', 'TXM', def='GLOBAL', into='GLOBAL LOCAL')
        call c%key('SYME', 'TXM', def='OUI', into=OUI_NON)
    end subroutine describe_discrete

    subroutine describe_functions(c)
        type(catalog_t), intent(inout) :: c
        character(len=*), parameter :: PROL = 'EXCLU CONSTANT LINEAIRE'
        call c%command('DEFI_CONSTANTE', 'fonction')
        call c%key('NOM_RESU', 'TXM', def='TOUTRESU', noop=.true.)
        call c%key('VALE', 'R', req=.true.)

        call c%command('DEFI_FONCTION', 'fonction')
        call c%key('NOM_PARA', 'TXM', req=.true., &
                   into='INST X Y Z ABSC EPSI SIGM TEMP DX DY DZ FREQ PULS')
        call c%key('NOM_RESU', 'TXM', def='TOUTRESU', noop=.true.)
        call c%key('VALE', 'R', min=2, max=MANY)
        call c%key('ABSCISSE', 'R', max=MANY)
        call c%key('ORDONNEE', 'R', max=MANY)
        call c%rule(RULE_UN_PARMI, 'VALE ABSCISSE')
        call c%key('INTERPOL', 'TXM', max=2, def='LIN LIN', into='LIN')
        call c%key('PROL_GAUCHE', 'TXM', def='EXCLU', into=PROL)
        call c%key('PROL_DROITE', 'TXM', def='EXCLU', into=PROL)
        call c%key('VERIF', 'TXM', def='CROISSANT', into='CROISSANT NON', noop=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', max=MANY, noop=.true.)

        call c%command('FORMULE', 'formule', open_keywords=.true.)
        call c%key('NOM_PARA', 'TXM', max=MANY, req=.true.)
        call c%key('VALE', 'TXM', req=.true.)

        call c%command('DEFI_LIST_REEL', 'listr8')
        call c%key('VALE', 'R', max=MANY, vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('DEBUT', 'R', vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%fact('INTERVALLE', max=MANY)
        call c%key('JUSQU_A', 'R', req=.true., vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('PAS', 'R', vmin=-MAX_INSTANT, vmax=MAX_INSTANT)
        call c%key('NOMBRE', 'I')
        call c%rule(RULE_UN_PARMI, 'PAS NOMBRE')
        call c%end_fact()
        call c%rule(RULE_UN_PARMI, 'VALE DEBUT')
        call c%rule(RULE_EXCLUS, 'VALE INTERVALLE')
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('TITRE', 'TXM', max=MANY, noop=.true.)
    end subroutine describe_functions

    subroutine describe_loads(c)
        type(catalog_t), intent(inout) :: c
        call describe_load_command(c, 'AFFE_CHAR_MECA', 'R')
        call describe_load_command(c, 'AFFE_CHAR_MECA_F', 'FUNC')
        call describe_kinematic_load(c, 'AFFE_CHAR_CINE', 'R')
        call describe_kinematic_load(c, 'AFFE_CHAR_CINE_F', 'FUNC')
    end subroutine describe_loads

    !> AFFE_CHAR_CINE / AFFE_CHAR_CINE_F (Code_Aster U4.44.03): imposed values eliminated
    !> from the system (no Lagrange multipliers), MECA_IMPO only; NOEUD in the real form only.
    subroutine describe_kinematic_load(c, name, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, vtype
        call c%command(name, 'char_cine_meca')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%fact('MECA_IMPO', max=MANY, req=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        if (vtype == 'R') then
            call c%key('NOEUD', 'TXM', max=MANY)
            call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA GROUP_NO NOEUD')
        else
            call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA GROUP_NO')
        end if
        call add_components(c, 'DX DY DZ DRX DRY DRZ', vtype)
        call c%end_fact()
    end subroutine describe_kinematic_load

    !> AFFE_CHAR_MECA (values are reals) and AFFE_CHAR_MECA_F (values are functions).
    subroutine describe_load_command(c, name, vtype)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, vtype
        character(len=*), parameter :: DOFS = 'DX DY DZ DRX DRY DRZ'
        call c%command(name, 'char_meca')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('VERI_NORM', 'TXM', into=OUI_NON, noop=.true.)
        call c%fact('DDL_IMPO', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_NO GROUP_MA NOEUD')
        call c%key('BLOCAGE', 'TXM', max=2, into='DEPLACEMENT ROTATION')
        call add_components(c, DOFS, vtype, also='BLOCAGE', bound=MAX_LENGTH)  ! lengths, angles
        call c%end_fact()
        call c%fact('FORCE_NODALE', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'GROUP_NO NOEUD')
        call add_components(c, 'FX FY FZ MX MY MZ', vtype)
        call c%end_fact()
        call c%fact('FORCE_COQUE', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call add_components(c, 'PRES FX FY FZ', vtype)
        call c%rule(RULE_EXCLUS, 'PRES FX')
        call c%rule(RULE_EXCLUS, 'PRES FY')
        call c%rule(RULE_EXCLUS, 'PRES FZ')
        call c%end_fact()
        call c%fact('PRES_REP', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%key('PRES', vtype, req=.true.)
        call c%end_fact()
        call c%fact('FORCE_CONTOUR', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call add_components(c, 'FX FY', vtype)
        call c%end_fact()
    end subroutine describe_load_command

    !> Optional components (at least one of them, or of the keywords `also`) of a load
    !> factor keyword; real values within +-bound when given (functions are checked where
    !> they are evaluated, model_loads).
    subroutine add_components(c, names, vtype, also, bound)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: names, vtype
        character(len=*), intent(in), optional :: also
        real(dp), intent(in), optional :: bound
        integer :: i, j
        i = 1
        do while (i <= len_trim(names))
            j = index(names(i:) // ' ', ' ') + i - 1
            if (present(bound) .and. vtype == 'R') then
                call c%key(names(i:j - 1), vtype, vmin=-bound, vmax=bound)
            else
                call c%key(names(i:j - 1), vtype)
            end if
            i = j + 1
        end do
        if (present(also)) then
            call c%rule(RULE_AU_MOINS_UN, names // ' ' // also)
        else
            call c%rule(RULE_AU_MOINS_UN, names)
        end if
    end subroutine add_components

    subroutine describe_analyses(c)
        type(catalog_t), intent(inout) :: c
        call c%command('MECA_STATIQUE', 'evol_elas')
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

        call c%command('STAT_NON_LINE', 'evol_noli')
        call c%key('MODELE', 'modele', req=.true.)
        call c%key('CHAM_MATER', 'cham_mater', req=.true.)
        call c%key('CARA_ELEM', 'cara_elem')
        call c%fact('EXCIT', max=MANY, req=.true.)
        call c%key('CHARGE', 'char_meca|char_cine_meca', req=.true.)
        call c%key('FONC_MULT', 'FUNC')
        call c%key('TYPE_CHARGE', 'TXM', def='FIXE_CSTE', into='FIXE_CSTE', noop=.true.)
        call c%end_fact()
        call c%fact('COMPORTEMENT', max=MANY, req=.true.)
        call c%key('RELATION', 'TXM', def='ELAS', into='ELAS DIS_CHOC DIS_CONTACT')
        call c%key('DEFORMATION', 'TXM', def='PETIT', into='PETIT')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%end_fact()
        call c%fact('INCREMENT', req=.true.)
        call c%key('LIST_INST', 'listr8', req=.true.)
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

    !> SOLVEUR factor keyword of the analyses (defaults as Code_Aster's: METHODE='MUMPS',
    !> NPREC=8, STOP_SINGULIER='OUI'; RENUM's default depends on the method).
    subroutine describe_solver(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('SOLVEUR')
        call c%key('METHODE', 'TXM', def='MUMPS', into='LDLT MULT_FRONT MUMPS')
        call c%key('RENUM', 'TXM', into='RCMK METIS SANS AMD MD AMF PORD SCOTCH QAMD AUTO')
        call c%key('NPREC', 'I', def='8')
        call c%key('STOP_SINGULIER', 'TXM', def='OUI', into=OUI_NON)
        call c%key('ELIM_LAGR', 'TXM', noop=.true.)
        call c%key('PCENT_PIVOT', 'I', noop=.true.)
        call c%key('GESTION_MEMOIRE', 'TXM', noop=.true.)
        call c%key('RESI_RELA', 'R', noop=.true.)
        call c%key('POSTTRAITEMENTS', 'TXM', noop=.true.)
        call c%key('TYPE_RESOL', 'TXM', noop=.true.)
        call c%key('ACCELERATION', 'TXM', into='AUTO FR FR+ FR++ LR LR+ LR++')  ! MUMPS
        call c%key('LOW_RANK_SEUIL', 'R', noop=.true.)
        call c%key('MATR_DISTRIBUEE', 'TXM', noop=.true.)
        call c%key('PRETRAITEMENTS', 'TXM', noop=.true.)
        call c%key('FILTRAGE_MATRICE', 'R', noop=.true.)
        call c%key('MIXER_PRECISION', 'TXM', noop=.true.)
        call c%end_fact()
    end subroutine describe_solver

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

end module deck_catalog_data
