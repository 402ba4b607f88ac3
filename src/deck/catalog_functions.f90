!> The catalog of the function commands: DEFI_CONSTANTE, DEFI_FONCTION, FORMULE,
!> DEFI_LIST_REEL, DEFI_PRES_EC8.
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_functions
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI
    use kinds, only: dp
    use number_limits, only: MAX_INSTANT, MAX_LENGTH, MIN_LENGTH, MAX_MODULUS, MIN_MODULUS
    use catalog_result_functions, only: PARA_FONCTION
    implicit none
    private
    public :: describe_functions

    !> DEFI_PRES_EC8: largest |acceleration| (m/s^2: a billion billion g) and largest
    !> |PRES_SURF_LIBR|, parasol's own bounds so that rho * A * H and the pressure's sums
    !> stay finite (number_limits); Code_Aster gives them no range.
    real(dp), parameter :: MAX_ACCELERATION = 1.0e30_dp

contains

    subroutine describe_functions(c)
        type(catalog_t), intent(inout) :: c
        character(len=*), parameter :: PROL = 'EXCLU CONSTANT LINEAIRE'
        call c%command('DEFI_CONSTANTE', 'fonction')
        call c%key('NOM_RESU', 'TXM', def='TOUTRESU')
        call c%key('VALE', 'R', req=.true.)

        call c%command('DEFI_FONCTION', 'fonction')
        ! Any name of Code_Aster's C_PARA_FONCTION: the function keeps it as a label;
        ! the consumer (a load, a material, a table) decides which variable it binds.
        call c%key('NOM_PARA', 'TXM', req=.true., into=PARA_FONCTION)
        call c%key('NOM_RESU', 'TXM', def='TOUTRESU')
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

        call describe_defi_pres_ec8(c)
    end subroutine describe_functions

    !> DEFI_PRES_EC8 (Code_Aster defi_pres_ec8.py, U4.44.31): every number required but
    !> GRAVITE (default 0, val_min 0) and PRES_SURF_LIBR (default 0); NEWMARK 'PC+' or
    !> 'PC-' (default 'PC+'). Code_Aster bounds none of the others; the pressure divides by
    !> RAYON, HAUT_EAU and RHO_EAU, so parasol requires them > 0 (MIN_LENGTH, MIN_MODULUS)
    !> and bounds every number (number_limits, MAX_ACCELERATION).
    subroutine describe_defi_pres_ec8(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEFI_PRES_EC8', 'formule')
        call c%key('Z_FOND', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('RAYON', 'R', req=.true., vmin=MIN_LENGTH, vmax=MAX_LENGTH)
        call c%key('HAUT_EAU', 'R', req=.true., vmin=MIN_LENGTH, vmax=MAX_LENGTH)
        call c%key('RHO_EAU', 'R', req=.true., vmin=MIN_MODULUS, vmax=MAX_MODULUS)
        call c%key('ACCE_SP_H', 'R', req=.true., vmin=-MAX_ACCELERATION, vmax=MAX_ACCELERATION)
        call c%key('ACCE_FLEX_H_N', 'R', req=.true., vmin=-MAX_ACCELERATION, &
                   vmax=MAX_ACCELERATION)
        call c%key('ACCE_FLEX_V', 'R', req=.true., vmin=-MAX_ACCELERATION, vmax=MAX_ACCELERATION)
        call c%key('ACCE_SP_V', 'R', req=.true., vmin=-MAX_ACCELERATION, vmax=MAX_ACCELERATION)
        call c%key('ACCE_CONV_H', 'R', req=.true., vmin=-MAX_ACCELERATION, vmax=MAX_ACCELERATION)
        call c%key('GRAVITE', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_ACCELERATION)
        call c%key('PRES_SURF_LIBR', 'R', def='0.0', vmin=-MAX_MODULUS, vmax=MAX_MODULUS)
        call c%key('NEWMARK', 'TXM', def='PC+', into='PC+ PC-')
        ! EVAL: a table of the pressure's parts per occurrence (post/defi_pres_ec8_command)
        call c%fact('EVAL', max=MANY)
        call c%key('RHO', 'R', req=.true.)
        call c%key('LIST_H', 'R', max=MANY, vmin=0.0_dp)
        call c%key('LIST_R_FOND', 'R', max=MANY, vmin=0.0_dp)
        call c%rule(RULE_UN_PARMI, 'LIST_H LIST_R_FOND')
        call c%key('LIST_EPAIS', 'R', max=MANY, req=.true.)
        call c%key('THETA', 'R', def='0.0')
        call c%key('TABLE', 'CO', req=.true.)
        call c%end_fact()
    end subroutine describe_defi_pres_ec8

end module catalog_functions
