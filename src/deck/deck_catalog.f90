!> Types of the command catalog and the small builder used by deck_catalog_data (the one
!> place where the commands are described, as data, in Code_Aster's manner: keywords, types,
!> cardinality, defaults, allowed values, mandatory keywords, rules).
module deck_catalog
    use kinds, only: dp
    use strings, only: string_t
    use deck_value, only: append_string
    implicit none
    private

    !> "any number" for a maximum cardinality.
    integer, parameter, public :: MANY = huge(1)
    !> Rule kinds between keywords of one scope (Code_Aster's EXCLUS, UN_PARMI, AU_MOINS_UN;
    !> PRESENT_PRESENT: the first given needs all the others; PRESENT_ABSENT: the first given
    !> forbids the others; ENSEMBLE: all or none).
    integer, parameter, public :: RULE_EXCLUS = 1, RULE_UN_PARMI = 2, RULE_AU_MOINS_UN = 3, &
        RULE_PRESENT_PRESENT = 4, RULE_PRESENT_ABSENT = 5, RULE_ENSEMBLE = 6

    !> One keyword. `types` is a '|'-separated list of: I, R, TXM, a concept type name
    !> (maillage, modele, ..., with FUNC meaning fonction|formule and RESU meaning
    !> evol_elas|evol_noli), ANY. Factor keywords have is_factor and own the keywords whose
    !> `parent` is their index. `default` is the text of the default ('' = none); several
    !> values are blank-separated. `noop`: accepted for Code_Aster compatibility, no effect.
    !> vmin/vmax (when has_vmin/has_vmax): the inclusive range of a numeric value, as
    !> Code_Aster's val_min/val_max, or parasol's own bound (number_limits) where products
    !> formed from the value must stay finite; vtiny (has_vtiny): the smallest magnitude of a
    !> value that is not 0 (a stiffness whose inverse must stay finite).
    type, public :: kw_def_t
        character(len=:), allocatable :: name
        character(len=:), allocatable :: types
        logical :: has_vmin = .false., has_vmax = .false., has_vtiny = .false.
        real(dp) :: vmin = 0.0_dp, vmax = 0.0_dp, vtiny = 0.0_dp
        integer :: min = 1, max = 1
        logical :: mandatory = .false.
        logical :: is_factor = .false.
        logical :: noop = .false.
        character(len=:), allocatable :: default
        type(string_t), allocatable :: into(:)
        integer :: parent = 0
        integer :: bloc = 0            !< the conditional block it belongs to (0: none)
    end type kw_def_t

    !> A rule between keywords of a scope (parent = 0: the command, else a factor keyword);
    !> bloc /= 0: it applies only while that conditional block is active.
    type, public :: rule_t
        integer :: kind = RULE_EXCLUS
        integer :: parent = 0
        integer :: bloc = 0
        type(string_t), allocatable :: names(:)
    end type rule_t

    !> A conditional block of keywords (Code_Aster's BLOC): its keywords, rules and defaults
    !> exist only while its condition holds on the keywords written in its scope (parent, as
    !> for keywords) and its enclosing block (outer) is active. The condition is the
    !> conjunction of: every keyword of `present` given (Code_Aster's exists("K")), every
    !> keyword of `absent` not given (not exists("K")), and, when `key` is set, the value of
    !> `key` (written, else its default) one of `values` (equal_to("K", 'V') / is_in).
    !> `text` is the condition in words, for messages.
    type, public :: bloc_t
        integer :: parent = 0
        integer :: outer = 0
        type(string_t), allocatable :: present(:), absent(:), values(:)
        character(len=:), allocatable :: key, text
    end type bloc_t

    !> One command: name, result concept type ('' = no result), keywords and rules.
    !> open_keywords: other keywords are accepted as-is (FORMULE binds deck objects so).
    !> reentrant: Code_Aster's catalog attribute, 'n' (default: no `reuse`), or 'o'/'f'
    !> optionally followed by ':' and the keywords that name the concept modified in place
    !> ('o:MAILLAGE|GRILLE' for DEFI_GROUP, 'f:RESULTAT' for CALC_CHAMP): the command then
    !> accepts reuse=CONCEPT (doc/architecture.md, "reuse").
    type, public :: cmd_def_t
        character(len=:), allocatable :: name
        character(len=:), allocatable :: result_type
        character(len=:), allocatable :: reentrant
        logical :: open_keywords = .false.
        type(kw_def_t), allocatable :: kws(:)
        type(rule_t), allocatable :: rules(:)
        type(bloc_t), allocatable :: blocs(:)
        integer :: nkw = 0, nrule = 0, nbloc = 0
    end type cmd_def_t

    !> The catalog. `factor` is the factor keyword being described while building, `open_bloc`
    !> the conditional block.
    type, public :: catalog_t
        type(cmd_def_t), allocatable :: cmds(:)
        integer :: ncmd = 0
        integer, private :: factor = 0
        integer, private :: open_bloc = 0
    contains
        procedure :: find_command => catalog_find_command
        procedure :: command => catalog_add_command
        procedure :: key => catalog_add_keyword
        procedure :: fact => catalog_add_factor
        procedure :: end_fact => catalog_end_factor
        procedure :: rule => catalog_add_rule
        procedure :: bloc => catalog_add_bloc
        procedure :: end_bloc => catalog_end_bloc
    end type catalog_t

    public :: find_keyword, split_words

contains

    !> Index of command `name`, 0 if unknown.
    pure integer function catalog_find_command(self, name)
        class(catalog_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer :: k
        catalog_find_command = 0
        do k = 1, self%ncmd
            if (self%cmds(k)%name == name) then
                catalog_find_command = k
                return
            end if
        end do
    end function catalog_find_command

    !> Index in cmd%kws of keyword `name` in scope `parent` (0 = command level), 0 if none.
    pure integer function find_keyword(cmd, parent, name)
        type(cmd_def_t), intent(in) :: cmd
        integer, intent(in) :: parent
        character(len=*), intent(in) :: name
        integer :: k
        find_keyword = 0
        do k = 1, cmd%nkw
            if (cmd%kws(k)%parent == parent .and. cmd%kws(k)%name == name) then
                find_keyword = k
                return
            end if
        end do
    end function find_keyword

    !> Starts the description of a command.
    !>  name : command name;  result_type : concept type of its result ('' = none)
    !>  reentrant : Code_Aster's `reentrant` attribute (cmd_def_t), default 'n'
    subroutine catalog_add_command(self, name, result_type, open_keywords, reentrant)
        class(catalog_t), intent(inout) :: self
        character(len=*), intent(in) :: name, result_type
        logical, intent(in), optional :: open_keywords
        character(len=*), intent(in), optional :: reentrant
        type(cmd_def_t), allocatable :: bigger(:)
        if (.not. allocated(self%cmds)) allocate (self%cmds(32))
        if (self%ncmd == size(self%cmds)) then
            allocate (bigger(2 * size(self%cmds)))
            bigger(1:self%ncmd) = self%cmds(1:self%ncmd)
            call move_alloc(bigger, self%cmds)
        end if
        self%ncmd = self%ncmd + 1
        self%cmds(self%ncmd)%name = name
        self%cmds(self%ncmd)%result_type = result_type
        if (present(open_keywords)) self%cmds(self%ncmd)%open_keywords = open_keywords
        self%cmds(self%ncmd)%reentrant = 'n'
        if (present(reentrant)) self%cmds(self%ncmd)%reentrant = reentrant
        allocate (self%cmds(self%ncmd)%kws(16), self%cmds(self%ncmd)%rules(4), &
                  self%cmds(self%ncmd)%blocs(4))
        self%factor = 0
        self%open_bloc = 0
    end subroutine catalog_add_command

    !> Adds a simple keyword to the current scope (the open factor keyword, else the command).
    !>  types : see kw_def_t;  min, max : cardinality (default 1..1; min 0 is allowed)
    !>  req : mandatory;  def : default as text;  into : blank-separated allowed values
    !>  noop : accepted, no effect in parasol
    !>  vmin, vmax : inclusive range of each numeric value
    !>  vtiny : smallest magnitude of a value that is not 0
    subroutine catalog_add_keyword(self, name, types, min, max, req, def, into, noop, vmin, &
                                   vmax, vtiny)
        class(catalog_t), intent(inout) :: self
        character(len=*), intent(in) :: name, types
        integer, intent(in), optional :: min, max
        logical, intent(in), optional :: req, noop
        character(len=*), intent(in), optional :: def, into
        real(dp), intent(in), optional :: vmin, vmax, vtiny
        type(kw_def_t) :: kw
        if (present(vtiny)) then
            kw%has_vtiny = .true.
            kw%vtiny = vtiny
        end if
        if (present(vmin)) then
            kw%has_vmin = .true.
            kw%vmin = vmin
        end if
        if (present(vmax)) then
            kw%has_vmax = .true.
            kw%vmax = vmax
        end if
        kw%name = name
        kw%types = types
        kw%parent = self%factor
        kw%bloc = self%open_bloc
        if (present(min)) kw%min = min
        if (present(max)) kw%max = max
        if (present(req)) kw%mandatory = req
        if (present(noop)) kw%noop = noop
        kw%default = ''
        if (present(def)) kw%default = def
        if (present(into)) then
            call split_words(into, kw%into)
        else
            allocate (kw%into(0))
        end if
        call append_keyword(self%cmds(self%ncmd), kw)
    end subroutine catalog_add_keyword

    !> Opens a factor keyword; the following keywords belong to it until end_fact.
    !>  min, max : occurrences (default 1..1);  req : mandatory
    subroutine catalog_add_factor(self, name, max, req, noop)
        class(catalog_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        integer, intent(in), optional :: max
        logical, intent(in), optional :: req, noop
        type(kw_def_t) :: kw
        kw%name = name
        kw%types = 'FACT'
        kw%is_factor = .true.
        kw%parent = 0
        kw%bloc = self%open_bloc
        kw%default = ''
        allocate (kw%into(0))
        if (present(max)) kw%max = max
        if (present(req)) kw%mandatory = req
        if (present(noop)) kw%noop = noop
        call append_keyword(self%cmds(self%ncmd), kw)
        self%factor = self%cmds(self%ncmd)%nkw
        self%open_bloc = 0
    end subroutine catalog_add_factor

    !> Closes the open factor keyword (and returns to the command's blocks: a factor keyword
    !> opened inside a block at command level belongs to it).
    subroutine catalog_end_factor(self)
        class(catalog_t), intent(inout) :: self
        if (self%factor > 0) self%open_bloc = self%cmds(self%ncmd)%kws(self%factor)%bloc
        self%factor = 0
    end subroutine catalog_end_factor

    !> Opens a conditional block (Code_Aster's BLOC) in the current scope, inside the open
    !> block if any; the following keywords and rules belong to it until end_bloc. The
    !> condition is the conjunction of the parts given (see bloc_t):
    !>  exists : blank-separated keywords that must all be given (Code_Aster's exists)
    !>  absent : blank-separated keywords that must all be absent (not exists)
    !>  key, equals : keyword `key` must have one of the blank-separated values `equals`
    !>                (equal_to, is_in)
    subroutine catalog_add_bloc(self, exists, absent, key, equals)
        class(catalog_t), intent(inout) :: self
        character(len=*), intent(in), optional :: exists, absent, key, equals
        type(bloc_t) :: b
        type(bloc_t), allocatable :: bigger(:)
        character(len=:), allocatable :: text
        integer :: i
        b%parent = self%factor
        b%outer = self%open_bloc
        text = ''
        call split_words(optional_text(exists), b%present)
        call split_words(optional_text(absent), b%absent)
        call split_words(optional_text(equals), b%values)
        b%key = optional_text(key)
        do i = 1, size(b%present)
            call add_part(b%present(i)%s // ' given')
        end do
        do i = 1, size(b%absent)
            call add_part('no ' // b%absent(i)%s)
        end do
        if (len(b%key) > 0) then
            do i = 1, size(b%values)
                if (i == 1) call add_part(b%key // '=''' // b%values(i)%s // '''')
                if (i > 1) text = text // ' or ''' // b%values(i)%s // ''''
            end do
        end if
        b%text = text
        associate (c => self%cmds(self%ncmd))
            if (c%nbloc == size(c%blocs)) then
                allocate (bigger(2 * size(c%blocs)))
                bigger(1:c%nbloc) = c%blocs(1:c%nbloc)
                call move_alloc(bigger, c%blocs)
            end if
            c%nbloc = c%nbloc + 1
            c%blocs(c%nbloc) = b
            self%open_bloc = c%nbloc
        end associate
    contains
        subroutine add_part(part)
            character(len=*), intent(in) :: part
            if (len(text) > 0) text = text // ' and '
            text = text // part
        end subroutine add_part
    end subroutine catalog_add_bloc

    !> Closes the open conditional block (back to its enclosing one, if any).
    subroutine catalog_end_bloc(self)
        class(catalog_t), intent(inout) :: self
        if (self%open_bloc > 0) self%open_bloc = self%cmds(self%ncmd)%blocs(self%open_bloc)%outer
    end subroutine catalog_end_bloc

    pure function optional_text(text) result(out)
        character(len=*), intent(in), optional :: text
        character(len=:), allocatable :: out
        out = ''
        if (present(text)) out = text
    end function optional_text

    !> Adds a rule over blank-separated keyword names of the current scope.
    subroutine catalog_add_rule(self, kind, names)
        class(catalog_t), intent(inout) :: self
        integer, intent(in) :: kind
        character(len=*), intent(in) :: names
        type(rule_t), allocatable :: bigger(:)
        associate (c => self%cmds(self%ncmd))
            if (c%nrule == size(c%rules)) then
                allocate (bigger(2 * size(c%rules)))
                bigger(1:c%nrule) = c%rules(1:c%nrule)
                call move_alloc(bigger, c%rules)
            end if
            c%nrule = c%nrule + 1
            c%rules(c%nrule)%kind = kind
            c%rules(c%nrule)%parent = self%factor
            c%rules(c%nrule)%bloc = self%open_bloc
            call split_words(names, c%rules(c%nrule)%names)
        end associate
    end subroutine catalog_add_rule

    subroutine append_keyword(cmd, kw)
        type(cmd_def_t), intent(inout) :: cmd
        type(kw_def_t), intent(in) :: kw
        type(kw_def_t), allocatable :: bigger(:)
        if (cmd%nkw == size(cmd%kws)) then
            allocate (bigger(2 * size(cmd%kws)))
            bigger(1:cmd%nkw) = cmd%kws(1:cmd%nkw)
            call move_alloc(bigger, cmd%kws)
        end if
        cmd%nkw = cmd%nkw + 1
        cmd%kws(cmd%nkw) = kw
    end subroutine append_keyword

    !> Splits blank-separated words.
    pure subroutine split_words(text, words)
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(out) :: words(:)
        integer :: i, j, n
        allocate (words(0))
        n = len_trim(text); i = 1
        do while (i <= n)
            if (text(i:i) == ' ') then
                i = i + 1; cycle
            end if
            j = i
            do while (j <= n)
                if (text(j:j) == ' ') exit
                j = j + 1
            end do
            call append_string(words, text(i:j - 1))
            i = j
        end do
    end subroutine split_words

end module deck_catalog
