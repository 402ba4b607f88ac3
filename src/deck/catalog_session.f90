!> The session commands of the catalog: DEBUT, POURSUITE, FIN, DEBUG (U4.11.01, U4.11.03,
!> U4.11.02; code_aster/Cata/Commands/debut.py, fin.py, debug.py), DEFI_FICHIER (U4.12.03,
!> defi_fichier.py) and DETRUIRE (U4.14.01, detruire.py).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_session
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN
    use catalog_common, only: OUI_NON
    implicit none
    private
    public :: describe_session

    !> Logical units a deck may name: Fortran's (Code_Aster's LogicalUnitFile hands out 19
    !> to 99; 6 and 8 are its listings).
    real(dp), parameter :: UNIT_MIN = 1.0_dp, UNIT_MAX = 99.0_dp

contains

    subroutine describe_session(c)
        type(catalog_t), intent(inout) :: c
        ! DEBUT (U4.11.01) and POURSUITE (U4.11.03, Code_Aster's DEBUT with caller
        ! POURSUITE: the same keywords): they steer Code_Aster's database, messages and
        ! time and memory reserves; parasol runs the session (session_commands), the
        ! keywords are checked and have no effect.
        call c%command('DEBUT', '')
        call describe_starter(c)
        call c%command('POURSUITE', '')
        call describe_starter(c)

        ! FIN (U4.11.02): the end of the command file (session_commands).
        call c%command('FIN', '')
        call c%key('RETASSAGE', 'TXM', def='NON', into=OUI_NON, noop=.true.)
        call c%key('INFO_BASE', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('INFO_RESU', 'TXM', def='NON', into=OUI_NON, noop=.true.)
        call c%key('FORMAT_HDF', 'TXM', into=OUI_NON, noop=.true.)   ! deprecated, dropped
        call c%key('PROC0', 'TXM', into=OUI_NON, noop=.true.)        ! deprecated, dropped
        call c%key('UNITE', 'I', noop=.true.)                         ! older catalogs

        ! DEBUG (debug.py): developers' checks between two commands; no effect.
        call c%command('DEBUG', '')
        call c%key('SDVERI', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('JXVERI', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('JEVEUX', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('IMPR_MACRO', 'TXM', into=OUI_NON, noop=.true.)
        ! MAJ_CATA (maj_cata.py): Code_Aster compiles its element catalogs; nothing to do.
        call c%command('MAJ_CATA', '')
        call c%rule(RULE_UN_PARMI, 'ELEMENT TYPE_ELEM')
        call c%fact('ELEMENT', noop=.true.)
        call c%end_fact()
        call c%fact('TYPE_ELEM', noop=.true.)
        call c%end_fact()
        call c%key('UNITE', 'I', def='8', noop=.true.)

        call describe_defi_fichier(c)

        ! DETRUIRE (U4.14.01): forgets the names of concepts (CONCEPT=_F(NOM=...) and OBJET
        ! are Code_Aster's older syntax, still accepted by its compat_syntax).
        call c%command('DETRUIRE', '')
        call c%key('NOM', 'assd', max=MANY)
        call c%fact('CONCEPT', max=MANY)
        call c%key('NOM', 'assd', max=MANY, req=.true.)
        call c%end_fact()
        call c%fact('OBJET', max=MANY, noop=.true.)
        call c%key('CHAINE', 'TXM', max=MANY)
        call c%key('POSITION', 'I', max=MANY)
        call c%end_fact()
        call c%rule(RULE_AU_MOINS_UN, 'NOM CONCEPT OBJET')
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_session

    !> The keywords of DEBUT and POURSUITE (debut.py), with the deprecated PAR_LOT and
    !> FORMAT_HDF its compat_syntax drops; CODE may also be an old _F(...).
    subroutine describe_starter(c)
        type(catalog_t), intent(inout) :: c
        call c%key('IMPR_MACRO', 'TXM', def='NON', into=OUI_NON, noop=.true.)
        call c%fact('BASE', max=2, noop=.true.)
        call c%key('FICHIER', 'TXM', req=.true., into='GLOBALE VOLATILE')
        call c%key('TITRE', 'TXM')
        call c%key('CAS', 'TXM')
        call c%key('NMAX_ENRE', 'I')
        call c%key('LONG_ENRE', 'I')
        call c%key('LONG_REPE', 'I')
        call c%key('TAILLE', 'I')
        call c%end_fact()
        call c%fact('CATALOGUE', max=10, noop=.true.)
        call c%key('FICHIER', 'TXM', req=.true.)
        call c%key('UNITE', 'I', vmin=UNIT_MIN, vmax=UNIT_MAX)
        call c%end_fact()
        call c%key('CODE', 'ANY', noop=.true.)          ! 'OUI'/'NON', or an old _F(...)
        call c%fact('ERREUR', noop=.true.)
        call c%key('ERREUR_F', 'TXM', into='ABORT EXCEPTION')
        call c%key('ALARME', 'TXM', into='ALARME EXCEPTION')
        call c%end_fact()
        call c%fact('DEBUG', noop=.true.)
        call c%key('JXVERI', 'TXM', def='NON', into=OUI_NON)
        call c%key('SDVERI', 'TXM', def='NON', into=OUI_NON)
        call c%key('JEVEUX', 'TXM', def='NON', into=OUI_NON)
        call c%key('ENVIMA', 'TXM', into='TEST')
        call c%key('VERI_BASE', 'TXM', into='GLOBALE VOLATILE')
        call c%key('VERI_BASE_NB', 'I', def='125')
        call c%key('HIST_ETAPE', 'ANY')                 ! deprecated, dropped
        call c%end_fact()
        call c%fact('MESURE_TEMPS', noop=.true.)
        call c%key('NIVE_DETAIL', 'I', def='1', into='0 1 2 3')
        call c%key('MOYENNE', 'TXM', def='NON', into=OUI_NON)
        call c%end_fact()
        call c%fact('MEMOIRE', noop=.true.)
        call c%key('TAILLE_BLOC', 'R', def='800.0')
        call c%key('TAILLE_GROUP_ELEM', 'I', def='1000')
        call c%end_fact()
        call c%fact('RESERVE_CPU', noop=.true.)
        call c%key('VALE', 'I', vmin=0.0_dp)
        call c%key('POURCENTAGE', 'R', vmin=0.0_dp, vmax=1.0_dp)
        call c%rule(RULE_EXCLUS, 'VALE POURCENTAGE')
        call c%end_fact()
        call c%fact('RESERVE_MEMOIRE', noop=.true.)
        call c%key('VALE', 'I', vmin=0.0_dp)
        call c%key('POURCENTAGE', 'R', vmin=0.0_dp, vmax=1.0_dp)
        call c%rule(RULE_EXCLUS, 'VALE POURCENTAGE')
        call c%end_fact()
        call c%key('IGNORE_ALARM', 'TXM', max=MANY, noop=.true.)
        call c%key('LANG', 'TXM', noop=.true.)
        call c%key('INFO', 'I', def='1', into='1 2', noop=.true.)
        call c%key('MODE', 'TXM', def='AUTO', into='AUTO DEBUT POURSUITE', noop=.true.)
        call c%key('PAR_LOT', 'TXM', into=OUI_NON, noop=.true.)         ! deprecated, dropped
        call c%key('FORMAT_HDF', 'TXM', into=OUI_NON, noop=.true.)      ! deprecated, dropped
    end subroutine describe_starter

    !> DEFI_FICHIER (U4.12.03, defi_fichier.py): associates a logical unit and a file
    !> (ASSOCIER), reserves one (RESERVER) or frees it (LIBERER); without UNITE, ASSOCIER
    !> and RESERVER give a free unit as the command's result (an integer).
    subroutine describe_defi_fichier(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEFI_FICHIER', 'entier')
        call c%key('ACTION', 'TXM', def='ASSOCIER', into='ASSOCIER LIBERER RESERVER')
        call c%bloc(key='ACTION', equals='ASSOCIER')
        call c%rule(RULE_AU_MOINS_UN, 'FICHIER UNITE')
        call c%key('UNITE', 'I', vmin=UNIT_MIN, vmax=UNIT_MAX)
        call c%key('FICHIER', 'TXM')
        call c%key('TYPE', 'TXM', def='ASCII', into='ASCII BINARY LIBRE')
        call c%bloc(key='TYPE', equals='ASCII')
        call c%key('ACCES', 'TXM', def='NEW', into='NEW APPEND OLD')
        call c%end_bloc()
        call c%bloc(key='TYPE', equals='BINARY LIBRE')
        call c%key('ACCES', 'TXM', def='NEW', into='NEW OLD')
        call c%end_bloc()
        call c%end_bloc()
        call c%bloc(key='ACTION', equals='RESERVER')
        call c%rule(RULE_AU_MOINS_UN, 'FICHIER UNITE')
        call c%key('UNITE', 'I', vmin=UNIT_MIN, vmax=UNIT_MAX)
        call c%key('FICHIER', 'TXM')
        call c%key('TYPE', 'TXM', def='ASCII', into='ASCII')
        call c%key('ACCES', 'TXM', def='APPEND', into='APPEND')
        call c%end_bloc()
        call c%bloc(key='ACTION', equals='LIBERER')
        call c%rule(RULE_UN_PARMI, 'FICHIER UNITE')
        call c%key('UNITE', 'I', vmin=UNIT_MIN, vmax=UNIT_MAX)
        call c%key('FICHIER', 'TXM')
        call c%end_bloc()
        call c%key('INFO', 'I', into='1 2')
    end subroutine describe_defi_fichier

end module catalog_session
