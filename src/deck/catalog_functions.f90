!> The catalog of the function commands: DEFI_CONSTANTE, DEFI_FONCTION, FORMULE,
!> DEFI_LIST_REEL.
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_functions
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI
    use number_limits, only: MAX_INSTANT
    use catalog_result_functions, only: PARA_FONCTION
    implicit none
    private
    public :: describe_functions

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
    end subroutine describe_functions

end module catalog_functions
